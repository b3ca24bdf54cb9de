# Request: a steady rest for my wood lathe, cut from 12 mm birch ply. An upright frame
# 320 mm wide with a round top (radius 160), the work's centre 200 mm above the lathe bed,
# and a 180 mm opening round that centre. Three radial slots for M8 bolts (8.5 mm wide)
# at 90, 210 and 330 deg, their bolt centres running from 100 to 145 mm out from the
# centre. Three arms 100 x 30 mm with round ends: an 8 mm axle hole for a 22 mm skate
# bearing at the inner end and an 8.5 mm bolt hole 70 mm from it. The frame stands in a
# 320 x 160 mm base (R10 corners) on two glued 60 mm tenons; two right-angle gussets
# 100 x 120 mm brace it from behind, each on a 40 mm tenon. A 13 mm wide slot, 90 mm
# long, behind the frame for the bed bolt. "STEADY REST" engraved 14 mm high under the
# opening, "CENTRE 200" 6 mm under that.
# FIX after the first valid program: the gussets were 120 high, their tips 3 mm under the
# lower slots' outer ends, where the M8 nut and washer go behind the frame: now 95 high;
# the letters are engraved filled (fill=true), not as outlines.

import "std/joints.aidl"

t = 12 mm
thickness t

centre_h = 200 mm
frame_w = 320 mm
opening_d = 180 mm
arm_hole = 70 mm        # from the bearing axle to the arm's bolt
fy = -30 mm             # the frame's back face on the base (3D y)
gx = [-136 mm, 124 mm]  # the gussets' left faces (3D x)

def arm_angle(i) = 90 deg + i * 120 deg

assembly steady_rest {
    solid frame {
        body = Hull(Circle(center=(0, centre_h), radius=frame_w / 2),
                    Rectangle(center=(0, centre_h / 2), width=frame_w, height=centre_h))
        hole opening { c = Circle(center=(0, centre_h), diameter=opening_d) }
        for i in range(3) {
            hole track {
                s = Slot(start=(100 mm * cos(arm_angle(i)), centre_h + 100 mm * sin(arm_angle(i))),
                         end=(145 mm * cos(arm_angle(i)), centre_h + 145 mm * sin(arm_angle(i))),
                         width=8.5 mm)
            }
        }
        tenons = tab_and_slot(part="tab", length=frame_w, thickness=t, tabs=2, tab=60 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        drawing label {
            name = Text("STEADY REST", position=(0, 70), size=14, font="sans:Bold", fill=true)
            sub = Text("CENTRE 200", position=(0, 40), size=6, font="sans", fill=true)
        }
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=320, height=160, corner_radius=10)
        frame_mortise = tab_and_slot(part="slot", length=frame_w, thickness=t, tabs=2,
                                     tab=60 mm, screw=0, cx=0 mm, cy=fy - t / 2)
        for i in range(2) {
            gusset_mortise = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=1,
                                          tab=40 mm, screw=0, rotation=90 deg,
                                          cx=gx[i] + t / 2, cy=fy + 50 mm)
        }
        hole bed_bolt { s = Slot(center=(0, fy + 10 mm + 45 mm), length=90, width=13, rotation=90) }
    }

    for i in range(2) {
        solid gusset {
            web = Polygon([(0, 0), (100, 0), (0, 95)])
            tenon = tab_and_slot(part="tab", length=100 mm, thickness=t, tabs=1, tab=40 mm,
                                 screw=0, rotation=180 deg, cx=50 mm, cy=0 mm)
        }
        Place(gusset, position=(gx[i], fy, 0), face="right", up="up")
        Above(gusset, base, gap=10)
        gusset.bb.left == base.bb.left + i * 115 mm
    }

    for i in range(3) {
        solid arm {
            bar = Slot(center=(35, 0), length=100, width=30)
            hole axle { c = Circle(center=(0, 0), diameter=8) }
            hole bolt { c = Circle(center=(arm_hole, 0), diameter=8.5) }
        }
        # bolt at 120 mm out: the bearing's axle 50 mm from the centre
        Place(arm, on=frame, position=(50 mm * cos(arm_angle(i)), centre_h + 50 mm * sin(arm_angle(i))),
              rotation=(0, 0, arm_angle(i)))
        RightOf(arm, base, gap=10)
        arm.bb.bottom == base.bb.bottom + i * 40 mm
    }

    Place(base, position=(0, 0, 0))
    Place(frame, position=(0, fy, 0), face="front", up="up")
    RightOf(base, frame, gap=10)
    AlignBottom(base, frame)

    assert frame.opening.c.center.y - frame.bb.bottom == 200 mm, "centre 200 above the bed"
    assert frame.body.bb.width == 320 mm
    assert frame.opening.c.diameter == 180 mm
    assert len(frame.track) == 3
    assert len(arm) == 3
    assert len(gusset) == 2
    # a 16 mm washer at a lower slot's outer end stays clear of the gusset's tip
    assert centre_h + 145 mm * sin(arm_angle(1)) - 8 mm - gusset[0].web.bb.top >= 5 mm
    assert base.plate.bb.width == 320 mm and base.plate.bb.height == 160 mm
    assert distance(arm[0].axle.c.center, arm[0].bolt.c.center) == 70 mm
    assert frame.track[0].s.length == 45 mm + 8.5 mm, "bolt centres from 100 to 145 out"
    assert base.bed_bolt.s.length == 90 mm and base.bed_bolt.s.width == 13 mm
    assert frame.label.name.size == 14 mm and frame.label.sub.size == 6 mm
}
