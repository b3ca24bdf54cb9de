# Request: a guard that stops the cat digging in a house plant's pot. 3 mm ply, a 190 mm disc
# that lies on the soil inside a 200 mm pot, made as two halves that close round the stem
# (a 30 mm stem hole in the middle) and lock along the seam with two sliding dovetails, one
# each side of the stem hole: 60 mm long, 8 mm deep, one tail each, centred 52.5 mm from the
# middle, 0.15 mm clearance. Watering holes 8 mm: 12 on a 140 mm circle and 8 on an 80 mm
# circle, none on the seam (each half gets half). A filled paw print engraved on the back half,
# "NO DIGGING" engraved along the front half's rim, readable.

thickness 3 mm
import "std/joints.aidl"

param r_out = 95 mm

assembly pot_guard {
    solid back_half {
        body = Sector(center=(0, 0), radius=r_out, start_angle=0, end_angle=180)
        hole stem { c = Circle(center=(0, 0), diameter=30) }
        sock_l = dovetail(part="socket", length=60, depth=8, tails=1, angle=10 deg,
                          clearance=0.15, cx=-52.5, cy=0)
        sock_r = dovetail(part="socket", length=60, depth=8, tails=1, angle=10 deg,
                          clearance=0.15, cx=52.5, cy=0)
        hole outer {
            o = Circle(center=(70 * cos(15 deg), 70 * sin(15 deg)), diameter=8)
        }
        outer_ring = CircularPattern(outer, 6, (0, 0), step=30 deg)
        hole inner {
            i = Circle(center=(40 * cos(22.5 deg), 40 * sin(22.5 deg)), diameter=8)
        }
        inner_ring = CircularPattern(inner, 4, (0, 0), step=45 deg)
        drawing paw {
            pad = Ellipse(center=(0, 50), rx=7, ry=5.5, fill=true)
            t1 = Circle(center=(-9, 58), radius=2.5, fill=true)
            t2 = Circle(center=(-3.5, 62), radius=2.5, fill=true)
            t3 = Circle(center=(3.5, 62), radius=2.5, fill=true)
            t4 = Circle(center=(9, 58), radius=2.5, fill=true)
        }
        Fixed(body)
    }

    solid front_half {
        body = Sector(center=(0, 0), radius=r_out, start_angle=180, end_angle=360)
        # the bands the tails are left in reach 8 mm across the seam
        band_l = Rectangle(bottom_left=(-82.5, 0), width=60, height=8)
        band_r = Rectangle(bottom_left=(22.5, 0), width=60, height=8)
        hole stem { c = Circle(center=(0, 0), diameter=30) }
        tail_l = dovetail(part="tail", length=60, depth=8, tails=1, angle=10 deg, cx=-52.5, cy=0)
        tail_r = dovetail(part="tail", length=60, depth=8, tails=1, angle=10 deg, cx=52.5, cy=0)
        hole outer {
            o = Circle(center=(70 * cos(195 deg), 70 * sin(195 deg)), diameter=8)
        }
        outer_ring = CircularPattern(outer, 6, (0, 0), step=30 deg)
        hole inner {
            i = Circle(center=(40 * cos(202.5 deg), 40 * sin(202.5 deg)), diameter=8)
        }
        inner_ring = CircularPattern(inner, 4, (0, 0), step=45 deg)
        drawing words {
            rim = Circle(center=(0, 0), radius=87, construction=true)
            t = Text("NO DIGGING", along=rim, size=7, flip=true)
        }
        Fixed(body)
    }

    # flat on the sheet: apart; in 3D: closed round the stem on the soil
    Below(front_half, back_half, gap=10)
    AlignLeft(front_half, back_half)
    Place(back_half, position=(0, 0, 0), face="up")
    Place(front_half, position=(0, 0, 0), face="up")

    assert 2 * r_out == 190 mm, "190 disc"
    assert back_half.stem.c.diameter == 30 mm, "stem 30"
    assert len(back_half.outer_ring) + len(front_half.outer_ring) == 12, "12 outer holes"
    assert len(back_half.inner_ring) + len(front_half.inner_ring) == 8, "8 inner holes"
    assert back_half.outer.o.diameter == 8 mm and front_half.inner.i.diameter == 8 mm, "8 mm holes"
    assert distance(back_half.outer.o.center, (0, 0)) == 70 mm, "140 circle"
    assert distance(front_half.inner.i.center, (0, 0)) == 40 mm, "80 circle"
}
