# Request (electronics): a bracket to stand a NEMA 17 stepper motor upright on a bench
# project, cut from 6 mm plywood. An upright plate 70 mm wide standing 60 mm above the base,
# with a 23 mm pilot hole for the motor's 22 mm centring boss, the shaft axis 32 mm above the
# base's top face, and four M3 clearance holes on the motor's 31 mm square. A base 110 x 80 mm
# with four M5 adjustment slots (12 mm long, 5.5 mm wide) centred 45 mm left/right and 30 mm
# front/back of the middle. The upright stands in the base on two 12 mm tabs with M3
# captive-nut T-slots (screwed). Two triangular gussets, 40 mm along the base and 50 mm up the
# upright, each with one 15 mm glued tab into the base and one into the upright, set 29 mm
# either side of the centre line so they clear the motor's 42.3 mm square body. "NEMA 17"
# engraved on the base behind the gussets.

import "std/joints.aidl"
import "std/fasteners.aidl"
import "std/shapes.aidl"

thickness 6 mm
kerf 0.15 mm

T = 6 mm
up_w = 70 mm        # upright width
up_h = 60 mm        # upright height above the base's top face
shaft_h = 32 mm     # shaft axis above the base's top face
g_run = 40 mm       # gusset along the base
g_rise = 50 mm      # gusset up the upright
g_x = 29 mm         # gusset centre planes from the centre line
up_y = 25 mm        # the upright's middle on the base (base frame)

def gusset() -> solid {
    web = Polygon([(0, 0), (g_run, 0), (0, g_rise)])
    foot = Rectangle(bottom_left=(0, -T), width=g_run, height=T)
    back = Rectangle(bottom_left=(-T, 0), width=T, height=g_rise)
    to_base = tab_and_slot(part="tab", length=g_run, thickness=T, tabs=1, tab=15 mm,
                           screw=0, rotation=180 deg, cx=g_run / 2, cy=-T)
    to_upright = tab_and_slot(part="tab", length=g_rise, thickness=T, tabs=1, tab=15 mm,
                              screw=0, rotation=90 deg, cx=-T, cy=g_rise / 2)
}

assembly bracket {
    solid upright {
        # drawn flat: the tabs' tips on y = 0, the shoulder (base top) at y = T
        plate = Rectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=up_h + T)
        feet = tab_and_slot(part="tab", length=up_w, thickness=T, tabs=2, tab=12 mm,
                            screw=3, rotation=180 deg, cx=0, cy=0)
        hole pilot { c = Circle(center=(0, T + shaft_h), diameter=23 mm) }
        m1 = clearance_hole(size=3, cx=-15.5, cy=T + shaft_h - 15.5)
        m2 = clearance_hole(size=3, cx=15.5, cy=T + shaft_h - 15.5)
        m3 = clearance_hole(size=3, cx=-15.5, cy=T + shaft_h + 15.5)
        m4 = clearance_hole(size=3, cx=15.5, cy=T + shaft_h + 15.5)
        gl = tab_and_slot(part="slot", length=g_rise, thickness=T, tabs=1, tab=15 mm,
                          screw=0, rotation=90 deg, cx=-g_x, cy=T + g_rise / 2)
        gr = tab_and_slot(part="slot", length=g_rise, thickness=T, tabs=1, tab=15 mm,
                          screw=0, rotation=90 deg, cx=g_x, cy=T + g_rise / 2)
        assert plate.width == 70 mm, "upright 70 mm wide"
        assert plate.height - T == 60 mm, "upright stands 60 mm above the base"
        assert pilot.c.center.y - T == 32 mm, "shaft axis 32 mm above the base"
        assert m2.c.center.x - m1.c.center.x == 31 mm, "motor holes on a 31 mm square"
        assert m3.c.center.y - m1.c.center.y == 31 mm, "motor holes on a 31 mm square"
        assert pilot.c.diameter == 23 mm, "pilot hole 23 mm"
        # the motor's 42.3 mm body clears the gussets (6 mm thick, centred on +-29)
        assert g_x - T / 2 - 42.3 mm / 2 >= 3 mm, "gussets clear the motor body"
        assert pilot.c.center.y - 42.3 mm / 2 > T, "motor body clears the base"
    }

    solid base {
        plate = Rectangle(center=(0, 0), width=110 mm, height=80 mm)
        up = tab_and_slot(part="slot", length=up_w, thickness=T, tabs=2, tab=12 mm,
                          screw=3, cx=0, cy=up_y)
        # gusset tabs: centred g_run / 2 behind the upright's back face
        gl = tab_and_slot(part="slot", length=g_run, thickness=T, tabs=1, tab=15 mm,
                          screw=0, rotation=90 deg, cx=-g_x, cy=up_y - T / 2 - g_run / 2)
        gr = tab_and_slot(part="slot", length=g_run, thickness=T, tabs=1, tab=15 mm,
                          screw=0, rotation=90 deg, cx=g_x, cy=up_y - T / 2 - g_run / 2)
        s1 = slot_hole(length=12 mm, width=5.5 mm, cx=-45, cy=-30)
        s2 = slot_hole(length=12 mm, width=5.5 mm, cx=45, cy=-30)
        s3 = slot_hole(length=12 mm, width=5.5 mm, cx=-45, cy=30)
        s4 = slot_hole(length=12 mm, width=5.5 mm, cx=45, cy=30)
        drawing label {
            t = Text("NEMA 17", position=(0, -30), size=6, valign="middle")
        }
        assert plate.width == 110 mm and plate.height == 80 mm, "base 110 x 80"
        assert s2.s.center.x == 45 mm and s4.s.center.y == 30 mm, "slots at 45 / 30 mm"
        assert label.bb.top < gl.bb.bottom, "label behind the gussets"
    }

    left_gusset = gusset()
    right_gusset = gusset()

    RightOf(upright, base, gap=10)
    AlignBottom(upright, base)
    Above(left_gusset, base, gap=12)
    AlignLeft(left_gusset, base)
    RightOf(right_gusset, left_gusset, gap=12)
    AlignBottom(right_gusset, left_gusset)
}
