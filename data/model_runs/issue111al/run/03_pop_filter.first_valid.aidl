# Request (music): a pop filter for a home-studio vocal mic, cut from 3 mm plywood. Two rings
# 160 mm across with a 136 mm opening clamp a layer of nylon stocking between them with six M3
# screws on a 148 mm circle (the first at 0 deg). The front ring has a 30 mm wide stem at the
# bottom whose end carries two dovetail tails (12 mm deep); a separate 30 mm wide mount bar
# takes them in its socket (0.1 mm clearance, glued) and ends in a C clip that snaps over a
# 20 mm mic-stand boom: a 20.5 mm bore with an 18 mm mouth out through the right-hand side,
# the bore 30 mm below the bar's top edge, 16 mm of material round it. "POP FILTER" engraved
# on the front ring's rim, centred at the top, 5 mm letters.

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 3 mm

ring_d = 160 mm
open_d = 136 mm
pcd = 148 mm
stem_w = 30 mm
tail_depth = 12 mm
stem_root = -76 mm    # the stem starts inside the rim
tail_line = -84 mm    # the tails' roots (the socket panel's edge)

def ring_plate() -> solid {
    body = Circle(center=(0, 0), diameter=ring_d)
    hole window { c = Circle(center=(0, 0), diameter=open_d) }
    screws = bolt_circle(count=6, pcd=pcd, hole_d=3.4 mm, start=0 deg)
}

assembly pop_filter {
    solid front {
        r = ring_plate()
        stem = Rectangle(corner=(-stem_w / 2, stem_root), opposite=(stem_w / 2, tail_line - tail_depth))
        tails = dovetail(part="tail", length=stem_w, depth=tail_depth, tails=2,
                         rotation=180 deg, cx=0, cy=tail_line)
        drawing label {
            track = Circle(center=(0, 0), radius=(ring_d + open_d) / 4, construction=true)
            t = Text("POP FILTER", along=track, angle=90 deg, size=5, valign="middle")
        }
        assert r.body.diameter == 160 mm, "rings 160 mm across"
        assert r.window.c.diameter == 136 mm, "136 mm opening"
        assert len(r.screws.bolt) == 6, "six M3 screws"
        assert stem.width == 30 mm, "30 mm stem"
    }

    solid back {
        r = ring_plate()
    }

    solid bar {
        # drawn with its top edge (the socket line) on y = 0
        upper = Rectangle(corner=(-stem_w / 2, 0), opposite=(stem_w / 2, -30 mm))
        boss = Circle(center=(0, -30 mm), radius=16 mm + 20.5 mm / 2)
        socket = dovetail(part="socket", length=stem_w, depth=tail_depth, tails=2,
                          clearance=0.1 mm, rotation=180 deg, cx=0, cy=0)
        hole clip {
            bore = Circle(center=(0, -30 mm), diameter=20.5 mm)
            mouth = Rectangle(corner=(0, -30 mm - 9 mm), opposite=(40 mm, -30 mm + 9 mm),
                              overrun=true)
        }
        assert clip.bore.diameter == 20.5 mm, "20.5 mm bore"
        assert clip.mouth.height == 18 mm, "18 mm mouth"
        assert upper.top.midpoint.y - clip.bore.center.y == 30 mm, "bore 30 mm below the top"
        assert boss.radius - clip.bore.radius == 16 mm, "16 mm of material round the bore"
    }

    RightOf(back, front, gap=10)
    AlignCenterY(back, front)
    RightOf(bar, back, gap=10)
    AlignTop(bar, back)
}
