# Request (bathroom): a tilting shaving mirror for the bathroom shelf. A 150 mm round,
# 3 mm mirror acrylic disc sits in a frame of three 3 mm birch-ply layers, all 180 mm
# round: a back disc, a spacer ring (151 mm opening, the mirror drops into it) and a
# front bezel ring (140 mm opening, a 5 mm lip over the mirror). Two 6 mm ply ears,
# 30 x 40 mm with round ends, tenon (16 mm) into mortises in the back disc 80 mm either
# side of its centre and stand out behind it; an M5 pivot bolt goes through each ear
# 22 mm behind the back disc into a 6 mm ply upright 40 mm wide with a round top. The
# pivot is 130 mm above the table. The uprights stand on two 10 mm tenons each in a 6 mm
# ply base 240 x 110 mm, corners 15 mm, which has "LOOK SHARP" engraved along its front
# edge (filled sans, 9 mm).

units mm
import "std/joints.aidl"

thickness 3 mm
PIVOT_Z = 130 mm
EAR_X = 80 mm          # ear centre line on the back disc
THIN = 3 mm
THICK = 6 mm

def ear() -> solid {
    thickness 6 mm
    body = RoundedRectangle(bottom_left=(-15, 0), width=30, height=40,
                            corner_radii=[15, 15, 0, 0])
    tenon = tab_and_slot(part="tab", length=30 mm, thickness=THIN, tabs=1, tab=16 mm,
                         screw=0, rotation=180 deg, cx=0, cy=0)
    hole pivot {
        c = Circle(center=(0, 25), diameter=5.5)
    }
}

def upright() -> solid {
    thickness 6 mm
    body = RoundedRectangle(bottom_left=(-20, 0), width=40, height=PIVOT_Z + 20,
                            corner_radii=[20, 20, 0, 0])
    feet = tab_and_slot(part="tab", length=40 mm, thickness=THICK, tabs=2, tab=10 mm,
                        screw=0, rotation=180 deg, cx=0, cy=0)
    hole pivot {
        c = Circle(center=(0, PIVOT_Z), diameter=5.5)
    }
}

assembly shaving_mirror {
    solid mirror {
        disc = Circle(center=(0, 0), diameter=150)
    }
    solid back {
        disc = Circle(center=(0, 0), diameter=180)
        m_l = tab_and_slot(part="slot", length=30 mm, thickness=THICK, tabs=1, tab=16 mm,
                           screw=0, clearance=0.1 mm, rotation=90 deg, cx=-EAR_X, cy=0)
        m_r = tab_and_slot(part="slot", length=30 mm, thickness=THICK, tabs=1, tab=16 mm,
                           screw=0, clearance=0.1 mm, rotation=90 deg, cx=EAR_X, cy=0)
    }
    solid spacer {
        ring = Circle(center=(0, 0), diameter=180)
        hole well { c = Circle(center=(0, 0), diameter=151) }
    }
    solid bezel {
        ring = Circle(center=(0, 0), diameter=180)
        hole window { c = Circle(center=(0, 0), diameter=140) }
    }
    ear_l = ear()
    ear_r = ear()
    up_l = upright()
    up_r = upright()
    solid base {
        thickness 6 mm
        body = RoundedRectangle(center=(0, 20), width=240, height=110, corner_radius=15)
        s_l = tab_and_slot(part="slot", length=40 mm, thickness=THICK, tabs=2, tab=10 mm,
                           screw=0, clearance=0.1 mm, rotation=90 deg, cx=-(EAR_X + 6), cy=31)
        s_r = tab_and_slot(part="slot", length=40 mm, thickness=THICK, tabs=2, tab=10 mm,
                           screw=0, clearance=0.1 mm, rotation=90 deg, cx=EAR_X + 6, cy=31)
        drawing motto {
            t = Text("LOOK SHARP", position=(0, -22), size=9, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # flat on the sheet: a row of round parts, the small ones under them
    RightOf(back, mirror, gap=10)
    RightOf(spacer, back, gap=10)
    RightOf(bezel, spacer, gap=10)
    AlignBottom(back, mirror)
    AlignBottom(spacer, mirror)
    AlignBottom(bezel, mirror)
    Below(base, mirror, gap=10)
    AlignLeft(base, mirror)
    RightOf(up_l, base, gap=10)
    RightOf(up_r, up_l, gap=10)
    RightOf(ear_l, up_r, gap=10)
    RightOf(ear_r, ear_l, gap=10)
    AlignTop(up_l, base)
    AlignTop(up_r, base)
    AlignTop(ear_l, base)
    AlignTop(ear_r, base)

    # standing: bezel face at y = 0, then mirror and spacer, then the back disc (y 6..9)
    Place(bezel, position=(0, 3, PIVOT_Z), face="front", up="up")
    Place(spacer, position=(0, 6, PIVOT_Z), face="front", up="up")
    Place(mirror, position=(0, 6, PIVOT_Z), face="front", up="up")
    Place(back, position=(0, 9, PIVOT_Z), face="front", up="up")
    # ears: tenon through the back disc (from y = 6), standing out behind it
    Place(ear_r, position=(EAR_X - 3, 6, PIVOT_Z), face="right", up="back")
    Place(ear_l, position=(-(EAR_X - 3), 6, PIVOT_Z), face="left", up="back")
    # uprights outside the ears, pivot hole on the ears' pivot (y = 6 + 25)
    Place(up_r, position=(EAR_X + 3, 31, 0), face="right", up="up")
    Place(up_l, position=(-(EAR_X + 3), 31, 0), face="left", up="up")
    Place(base, position=(0, 0, 0), face="up")

    assert mirror.disc.diameter == 150 mm, "mirror 150"
    assert back.disc.diameter == 180 mm and spacer.ring.diameter == 180 mm and bezel.ring.diameter == 180 mm, "frame 180"
    assert spacer.well.c.diameter == 151 mm, "spacer opening"
    assert (mirror.disc.diameter - bezel.window.c.diameter) / 2 == 5 mm, "5 mm lip"
    assert back.m_r.cx == 80 mm and back.m_l.cx == -80 mm, "ears 80 from centre"
    assert ear_r.pivot.c.center.y - THIN == 22 mm, "pivot 22 behind the back disc"
    assert up_r.pivot.c.center.y == 130 mm, "pivot 130 above the table"
    assert up_r.body.bb.width == 40 mm, "upright 40 wide"
    assert base.body.bb.width == 240 mm and base.body.bb.height == 110 mm, "base size"
    assert PIVOT_Z - 180 mm / 2 >= THICK + 20 mm, "mirror clears the base"
    assert base.motto.bb.width <= 240 mm - 2 * 20 mm, "motto fits"
}
