# A 6-spoke wheel, 100 mm across: an 8 mm wide rim, a 20 mm hub with a
# 5 mm axle hole, and six spokes made in a loop.

param wheel_d = 100 mm
param rim_w = 8 mm
param hub_d = 20 mm
param axle_d = 5 mm
param spokes = 6
param spoke_w = 6 mm

solid wheel {
    solid rim {
        outer = Circle(center=(0, 0), diameter=wheel_d)
        hole inside {
            c = Circle(center=(0, 0), diameter=wheel_d - 2 * rim_w)
        }
        Concentric(inside.c, outer)
    }
    Fixed(rim.outer)

    solid hub {
        c = Circle(center=(0, 0), diameter=hub_d)
    }
    Concentric(hub.c, rim.outer)

    # each spoke runs from inside the hub to inside the rim so they merge
    for i in range(spokes) {
        solid spoke {
            bar = Rectangle(start=((hub_d / 2 - 1) * cos(i * 360 deg / spokes), (hub_d / 2 - 1) * sin(i * 360 deg / spokes)),
                            end=((wheel_d / 2 - rim_w + 1) * cos(i * 360 deg / spokes), (wheel_d / 2 - rim_w + 1) * sin(i * 360 deg / spokes)),
                            width=spoke_w)
        }
    }

    hole axle {
        c = Circle(center=(0, 0), diameter=axle_d)
    }
    Concentric(axle.c, hub.c)
}
