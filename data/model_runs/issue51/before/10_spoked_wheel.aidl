# A 6-spoke wheel, 100 mm across: an 8 mm wide rim, a 20 mm hub with a 5 mm
# axle hole, and six spokes made in a loop.

param diameter = 100 mm
param rim_w = 8 mm
param hub_d = 20 mm
param axle_d = 5 mm
param spokes = 6
param spoke_w = 6 mm

r_in = diameter / 2 - rim_w          # inside of the rim
spoke_len = r_in - hub_d / 2 + 4 mm  # reaches 2 mm into hub and rim
spoke_mid = (r_in + hub_d / 2) / 2

solid wheel {
    solid rim {
        outer = Circle(center=(0, 0), diameter=diameter)
        hole well {
            c = Circle(center=(0, 0), radius=r_in)
        }
        Concentric(well.c, outer)
    }

    solid hub {
        boss = Circle(center=(0, 0), diameter=hub_d)
        hole axle {
            c = Circle(center=(0, 0), diameter=axle_d)
        }
        Concentric(axle.c, boss)
    }

    for i in range(spokes) {
        spoke = Rectangle(center=(spoke_mid * cos(i * 360 deg / spokes), spoke_mid * sin(i * 360 deg / spokes)),
                          width=spoke_len, height=spoke_w, rotation=i * 360 deg / spokes)
    }

    Fixed(hub.boss)
    Concentric(rim.outer, hub.boss)
    for i in range(spokes) {
        Distance(spoke[i].center, hub.boss.center, spoke_mid)
    }
}
