# Workshop: a honing-angle gauge for chisels and plane irons, cut from 3 mm acrylic.
# Plate 160 x 40 mm, corners R3. Along the bottom edge four notches, one per bevel
# angle 15, 20, 25 and 30 deg: each a right triangle with a vertical wall 10 mm deep
# and a sloped edge meeting the bottom edge at the angle; 10 mm of plate between
# notches, the first notch 8 mm from the left end. Each angle engraved above its
# notch ("15°" ..., 5 mm letters); a 6 mm hanging hole 10 mm in from the top right corner.

thickness 3 mm

param depth = 10 mm, min = 6 mm, max = 16 mm

angles = [15 deg, 20 deg, 25 deg, 30 deg]
labels = ["15°", "20°", "25°", "30°"]
runs = [depth / tan(a) for a in angles]
starts = [8 mm + i * 10 mm + sum([runs[j] for j in range(i)]) for i in range(4)]

solid gauge {
    plate = RoundedRectangle(bottom_left=(0, 0), width=160, height=40, corner_radius=3)
    Fixed(plate)

    hole notches {
        for i in range(4) {
            # the sloped edge runs on 1 mm below the plate so the cut opens cleanly
            t = Polygon([(starts[i] - 1 mm / tan(angles[i]), -1 mm),
                         (starts[i] + runs[i], -1 mm),
                         (starts[i] + runs[i], depth)])
        }
    }

    hole hang {
        c = Circle(center=(150, 30), diameter=6)
    }

    drawing marks {
        for i in range(4) {
            t = Text(labels[i], position=(starts[i] + runs[i] / 2, 22), size=5)
        }
    }

    assert plate.width == 160 mm and plate.height == 40 mm, "plate 160 x 40"
    assert len(notches.t) == 4, "four notches"
    assert starts[0] == 8 mm, "first notch 8 mm from the left end"
    assert starts[3] + runs[3] <= 160 mm - 12 mm, "last notch clear of the hanging hole"
    assert abs(atan2(depth, runs[0]) - 15 deg) < 0.01 deg, "first notch at 15 deg"
    assert abs(atan2(depth, runs[3]) - 30 deg) < 0.01 deg, "last notch at 30 deg"
    assert depth == 10 mm, "notches 10 mm deep"
    assert plate.bb.right - hang.c.center.x == 10 mm and plate.bb.top - hang.c.center.y == 10 mm, "hanging hole 10 mm in"
}
