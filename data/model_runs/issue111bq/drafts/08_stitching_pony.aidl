# Request: a leather-stitching pony, 6 mm birch ply. You sit on a 360 x 140 base (r15
# corners); two jaws stand up from its middle, 300 mm above the base, tapering from 90 mm
# wide at the base to 60 mm at the top (r10 top corners). A 46 mm tall spacer glued between
# them at the bottom keeps them 6 mm apart there, so the tops spring together on the leather;
# an M6 bolt with a wing nut through both jaws 50 mm below the top closes them. The jaws and
# spacer stand together in two 25 mm mortises of the base (18 mm wide, 0.1 mm clearance);
# two triangular fins (50 out, 110 high) brace the jaws front and back, each on one 25 mm
# tab. The front jaw carries an engraved pricking guide 12 mm below its top: a 48 mm line
# with a tick every 4 mm (the 5th ones longer), and the base the owner's initials "J.K."
# in filled bold 20 mm letters near one end.
units mm
thickness 6 mm
import "std/joints.aidl"
import "std/fasteners.aidl"

T = 6 mm
JAW_H = 300 mm + T          # from the tabs' tips (the base's underside)
JAW_B = 90 mm
JAW_TOP = 60 mm
SPACER_H = 46 mm
FIN_OUT = 50 mm
FIN_H = 110 mm
CL = 0.1 mm
PITCH = 4 mm

def jaw(guide=false) -> solid {
    body = Trapezoid(center=(0, JAW_H / 2), bottom_width=JAW_B, top_width=JAW_TOP, height=JAW_H)
    Fillet([body.top_left, body.top_right], 10)
    feet = tab_and_slot(part="tab", length=JAW_B, thickness=T, tabs=2, tab=25 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    bolt = clearance_hole(size=6, cx=0, cy=JAW_H - 50 mm)
    if guide {
        drawing pricking {
            line = Line((-24, JAW_H - 12 mm), (24, JAW_H - 12 mm))
            for i in range(13) {
                tick = Line((-24 + i * PITCH, JAW_H - 12 mm),
                            (-24 + i * PITCH, JAW_H - 12 mm - (5 mm if i % 5 == 0 else 3 mm)))
            }
        }
    }
}

def fin() -> solid {
    # x out from the jaw's face, y up from the base's underside
    body = Polygon([(0, 0), (FIN_OUT, 0), (FIN_OUT, 2 * T), (8, FIN_H), (0, FIN_H)])
    foot = tab_and_slot(part="tab", length=FIN_OUT, thickness=T, tabs=1, tab=25 mm, screw=0,
                        rotation=180 deg, cx=FIN_OUT / 2, cy=0)
}

assembly stitching_pony {
    solid base {
        seat = RoundedRectangle(center=(0, 0), width=360, height=140, corner_radius=15)
        # one mortise row for the jaws and spacer glued together (3 x 6 mm)
        mortise = tab_and_slot(part="slot", length=JAW_B, thickness=3 * T, tabs=2, tab=25 mm,
                               screw=0, clearance=CL, cx=0, cy=0)
        fin_f = tab_and_slot(part="slot", length=FIN_OUT, thickness=T, tabs=1, tab=25 mm,
                             screw=0, clearance=CL, rotation=90 deg, cx=0,
                             cy=-(1.5 * T + FIN_OUT / 2))
        fin_b = tab_and_slot(part="slot", length=FIN_OUT, thickness=T, tabs=1, tab=25 mm,
                             screw=0, clearance=CL, rotation=90 deg, cx=0,
                             cy=1.5 * T + FIN_OUT / 2)
        drawing initials {
            word = Text("J.K.", position=(130, 0), size=20, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    front_jaw = jaw(guide=true)
    back_jaw = jaw()
    solid spacer {
        body = Trapezoid(center=(0, SPACER_H / 2), bottom_width=JAW_B,
                         top_width=JAW_B - (JAW_B - JAW_TOP) * SPACER_H / JAW_H, height=SPACER_H)
        feet = tab_and_slot(part="tab", length=JAW_B, thickness=T, tabs=2, tab=25 mm, screw=0,
                            rotation=180 deg, cx=0, cy=0)
    }
    fin_a = fin()
    fin_b = fin()

    # on the sheet
    Above(front_jaw, base, gap=10)
    AlignLeft(front_jaw, base)
    RightOf(back_jaw, front_jaw, gap=8)
    AlignBottom(back_jaw, front_jaw)
    RightOf(spacer, back_jaw, gap=8)
    AlignBottom(spacer, back_jaw)
    RightOf(fin_a, spacer, gap=8)
    AlignBottom(fin_a, spacer)
    RightOf(fin_b, fin_a, gap=8)
    AlignBottom(fin_b, fin_a)

    # in 3D: x along the base, y across it, z up; front jaw, spacer, back jaw from -y to +y
    Place(base, position=(0, 0, 0))
    Place(front_jaw, rotation=(90 deg, 0, 0), position=(0, -T / 2, 0))
    Place(spacer, rotation=(90 deg, 0, 0), position=(0, T / 2, 0))
    Place(back_jaw, rotation=(90 deg, 0, 0), position=(0, 1.5 * T, 0))
    Place(fin_b, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 1.5 * T, 0))
    Place(fin_a, rotation=(90 deg, 0, -90 deg), position=(T / 2, -1.5 * T, 0))

    assert base.seat.bb.width == 360 mm and base.seat.bb.height == 140 mm, "base 360 x 140"
    assert front_jaw.body.bb.height - T == 300 mm, "jaws 300 above the base"
    assert front_jaw.body.bottom_width == 90 mm and front_jaw.body.top_width == 60 mm, "taper"
    assert front_jaw.body.bb.top - front_jaw.bolt.c.center.y == 50 mm, "bolt 50 below the top"
    assert spacer.body.bb.height == 46 mm, "spacer 46 tall"
    assert len(front_jaw.pricking.tick) == 13, "ticks over 48 mm"
    assert front_jaw.pricking.tick[1].start.x - front_jaw.pricking.tick[0].start.x == 4 mm,
        "a tick every 4 mm"
    assert front_jaw.body.bb.top - front_jaw.pricking.line.start.y == 12 mm, "guide 12 below top"
}
