# Holidays: a Christmas candle arch (Schwibbogen), 6 mm birch plywood, with two cross-halved feet.
# The arch panel: a base bar 320 x 30 mm and on it a semicircular band, outer radius 150 mm,
# 25 mm wide (inner radius 125), centred on the bar's top edge (180 mm tall overall). In the band
# 7 holes 8 mm across for LED candle lights on the band's middle radius (137.5 mm), at 15 deg and
# every 25 deg to 165 deg. Inside: a house 50 x 50 mm with a roof 62 wide and 30 tall, a window
# 10 x 12 and a door 12 x 24 cut out, centred 70 mm left of the middle; two fir trees (3 tiers,
# trunk 8 x 8; full size 66 mm tall at 30 mm right, 0.8 size at 80 mm right); a 5-point star
# (outer radius 15, inner 6) hanging from the arch's crown by a bar 5 mm wide. "FROHE WEIHNACHTEN"
# engraved single-stroke 10 mm tall, centred on the bar. Two feet 120 x 40 mm (top corners R10);
# cross-halving slots 6 mm wide: 20 mm up into the bar from its bottom edge at 120 mm either
# side of the middle, and 20 mm down into each foot from the middle of its top edge.
import "std/joints.aidl"

thickness 6 mm

def tree(x=0 mm, k=1) -> solid {
    trunk = Rectangle(center=(x, 4 * k - 1), width=8 * k, height=8 * k)
    t1 = Triangle(center=(x, (6 + 15) * k), base=44 * k, height=30 * k)
    t2 = Triangle(center=(x, (24 + 14) * k), base=36 * k, height=28 * k)
    t3 = Triangle(center=(x, (42 + 12) * k), base=26 * k, height=24 * k)
}

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=120, height=40, corner_radii=[10, 10, 0, 0])
    slot = cross_halving(depth=20 mm, thickness=6 mm, cx=0 mm, cy=20 mm)
}

assembly schwibbogen {
    solid arch {
        bar = Rectangle(center=(0, -15), width=320, height=30)
        band = Sector(center=(0, 0), radius=150, start_angle=0, end_angle=180, inner_radius=125)

        solid house {
            body = Rectangle(center=(-70, 24), width=50, height=50)
            roof = Triangle(center=(-70, 63), base=62, height=30)
            hole window { w = Rectangle(center=(-80, 30), width=10, height=12) }
            hole door { d = Rectangle(center=(-58, 12), width=12, height=24) }
        }
        big_tree = tree(x=30 mm, k=1)
        small_tree = tree(x=80 mm, k=0.8)

        solid star {
            s = Star(center=(0, 110), points=5, outer_radius=15, inner_radius=6)
            hanger = Rectangle(center=(0, 122), width=5, height=10)
        }

        hole leds {
            for i in range(7) {
                c = Circle(center=polar((0, 0), 137.5, 15 deg + i * 25 deg), diameter=8)
            }
        }
        left = cross_halving(depth=20 mm, thickness=6 mm, rotation=180 deg, cx=-120 mm, cy=-30 mm)
        right = cross_halving(depth=20 mm, thickness=6 mm, rotation=180 deg, cx=120 mm, cy=-30 mm)

        drawing greeting {
            t = Text("FROHE WEIHNACHTEN", position=(0, -15), size=10, valign="middle")
        }
    }
    foot_a = foot()
    foot_b = foot()
    Below(foot_a, arch, gap=10)
    AlignLeft(foot_a, arch)
    RightOf(foot_b, foot_a, gap=10)
    AlignTop(foot_b, foot_a)

    assert arch.bar.bb.width == 320 mm and arch.bar.bb.height == 30 mm, "bar 320 x 30"
    assert arch.band.radius == 150 mm and arch.band.inner_radius == 125 mm, "band R150, 25 wide"
    assert arch.bb.height == 180 mm, "180 tall"
    assert len(arch.leds.c) == 7, "7 lights"
    assert arch.leds.c[0].diameter == 8 mm, "8 mm lights"
    assert distance(arch.leds.c[3].center, arch.band.center) == 137.5 mm, "on the middle radius"
    assert arch.left.cut.bb.height == 20 mm and foot_a.slot.cut.bb.height == 20 mm, "20 + 20 mm slots"
    assert arch.left.cut.bb.width == 6 mm, "6 mm slots"
    assert arch.right.cut.bb.center_x - arch.bar.center.x == 120 mm, "slot 120 right of the middle"
    assert foot_a.body.bb.width == 120 mm and foot_a.body.bb.height == 40 mm, "feet 120 x 40"
    assert arch.left.depth + foot_a.slot.depth == foot_a.body.bb.height, "halvings add to the foot"
    assert arch.house.body.bb.width == 50 mm and arch.house.roof.bb.height == 30 mm, "house"
    assert arch.big_tree.bb.height == 66 mm, "tree 66 tall"
}
