# Request (science): a Hooke's-law spring stand for a school lab, 6 mm ply. Base 200 x 280 mm.
# An upright 60 mm wide standing 400 mm above the base on two 15 mm tenons through it. On its
# front face a scale in cm read downwards: 0 at 330 mm above the base to 30 at 30 mm above,
# a tick every mm (3 mm each side of the centre line, 6 at 5 mm, 10 at each cm), the cm
# numbers 13 mm left of the centre, and "HOOKE'S LAW" up its right side. At the top an arm
# gusset (60 tall at the upright, 150 long, 20 tall at its tip) with two 20 mm tenons
# through the upright, flush with its top, and a 5 mm spring-hook hole 120 mm out from the
# upright's front face, 10 mm under the arm's top. Behind, a triangular brace 120 x 150,
# 20 mm right of the centre, with three 20 mm tenons through the upright and two through the
# base. A pointer 130 x 15 with a 4 mm hook hole at 120 mm and a point that reaches the
# scale. On the base in front: "F = k x" in filled 10 mm letters.

units mm
thickness 6 mm

import "std/joints.aidl"

T = 6 mm
up_h = 400 mm
scale_top = 330 mm        # the 0 mark, above the base
brace_x = 20 mm
arm_len = 150 mm
hook_out = 120 mm

assembly hookes_stand {
    solid base {
        body = Rectangle(center=(0, -10), width=200, height=280)
        m_up = tab_and_slot(part="slot", length=60 mm, thickness=T, tabs=2, tab=15 mm, screw=0,
                            cx=0 mm, cy=0 mm)
        m_brace = tab_and_slot(part="slot", length=120 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                               rotation=90 deg, cx=brace_x, cy=T / 2 + 60 mm)
        drawing marks {
            law = Text("F = k x", position=(0, -125), size=10, font="sans:Bold", valign="middle",
                       fill=true)
        }
    }

    solid upright {
        body = Rectangle(bottom_left=(-30, 0), width=60, height=T + up_h)
        tenons = tab_and_slot(part="tab", length=60 mm, thickness=T, tabs=2, tab=15 mm, screw=0,
                              rotation=180 deg, cx=0 mm, cy=0 mm)
        m_arm = tab_and_slot(part="slot", length=60 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=0 mm, cy=T + up_h - 30 mm)
        m_brace = tab_and_slot(part="slot", length=150 mm, thickness=T, tabs=3, tab=20 mm, screw=0,
                               rotation=90 deg, cx=brace_x, cy=T + 75 mm)
        drawing scale {
            for i in range(301) {
                tick = Line((-(10 if i % 10 == 0 else (6 if i % 5 == 0 else 3)) * 1 mm, T + scale_top - i * 1 mm),
                            ((10 if i % 10 == 0 else (6 if i % 5 == 0 else 3)) * 1 mm, T + scale_top - i * 1 mm))
            }
            for j in range(31) {
                num = Text(str(j), position=(-13, T + scale_top - j * 10 mm), size=4, anchor="end",
                           valign="middle")
            }
            title = Text("HOOKE'S LAW", position=(22, T + 250 mm), size=8, font="sans:Bold",
                         valign="middle", rotation=90 deg, fill=true)
        }
    }

    solid arm {
        body = Polygon([(-T, 0), (-T, 60), (arm_len, 60), (arm_len, 40), (0, 0)])
        tenons = tab_and_slot(part="tab", length=60 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                              rotation=90 deg, cx=-T, cy=30 mm)
        hole hook { c = Circle(center=(hook_out, 50), diameter=5) }
    }

    solid brace {
        body = Polygon([(-T, 0), (-T, 150), (0, 150), (120, 0), (120, -T), (0, -T), (0, 0)])
        up_tenons = tab_and_slot(part="tab", length=150 mm, thickness=T, tabs=3, tab=20 mm, screw=0,
                                 rotation=90 deg, cx=-T, cy=75 mm)
        base_tenons = tab_and_slot(part="tab", length=120 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                                   rotation=180 deg, cx=60 mm, cy=-T)
    }

    solid pointer {
        body = Polygon([(0, 7.5), (10, 0), (130, 0), (130, 15), (10, 15)])
        hole hook { c = Circle(center=(hook_out, 7.5), diameter=4) }
    }

    # flat on the sheet
    RightOf(upright, base, gap=10)
    AlignTop(upright, base)
    RightOf(arm, upright, gap=10)
    AlignTop(arm, upright)
    Below(brace, arm, gap=10)
    AlignLeft(brace, arm)
    Below(pointer, brace, gap=10)
    AlignLeft(pointer, brace)

    # assembled: the upright in the x-z plane facing front (-y), arm out to the front
    Place(base, position=(0, 0, 0))
    Place(upright, position=(0, T / 2, 0), face="front", up="up")
    Place(arm, position=(T / 2, -T / 2, T + up_h - 60 mm), face="left", up="up")
    Place(brace, position=(brace_x - T / 2, T / 2, T), face="right", up="up")
    Place(pointer, position=(T / 2, -T / 2 - 1 mm, 290 mm), face="left", up="up")

    # the request's numbers
    assert base.body.bb.width == 200 mm and base.body.bb.height == 280 mm, "base 200 x 280"
    assert upright.body.bb.height - T == 400 mm and upright.body.bb.width == 60 mm, "upright 60 wide, 400 above"
    assert len(upright.scale.tick) == 301 and len(upright.scale.num) == 31, "a tick a mm, 0-30 cm"
    assert upright.scale.tick[0].start.y - upright.scale.tick[300].start.y == 300 mm, "30 cm long"
    assert upright.scale.tick[0].start.y - T == 330 mm, "0 at 330 above the base"
    assert upright.scale.tick[10].length == 20 mm and upright.scale.tick[5].length == 12 mm and upright.scale.tick[1].length == 6 mm,
        "tick lengths"
    assert arm.hook.c.center.x - 0 mm == 120 mm, "hook 120 out from the front face"
    assert arm.body.bb.top - arm.hook.c.center.y == 10 mm, "hook 10 under the top"
    assert arm.body.points[2].x - arm.body.points[4].x == 150 mm, "arm 150 long"
    assert arm.body.points[2].y - arm.body.points[3].y == 20 mm, "tip 20 tall"
    assert pointer.hook.c.center.x == arm.hook.c.center.x, "pointer hangs plumb under the hook"
    assert upright.m_brace.slot[0].bb.center_x - upright.body.bb.center_x == 20 mm, "brace 20 right of centre"
}
