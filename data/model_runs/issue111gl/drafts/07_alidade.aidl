# Request: an alidade (sighting rule) for our school's plane-table mapping, 6 mm birch ply.
# A rule 300 x 50 mm whose bottom long edge is the drawing edge, engraved along it with a
# 250 mm scale centred on the rule (ticks every mm 2 mm long, every 5 mm 3.5 mm, every 10 mm
# 6 mm, the centimetres 0-25 numbered 3 mm high above them), "CLASS 5B ALIDADE" engraved
# (5 mm) left of the middle and a 20.2 mm hole right of the middle for a 20 mm button compass.
# Two sight vanes 40 mm wide standing 120 mm above the rule (8 mm round top corners), their
# mid-planes 135 mm either side of the middle, each glued into the rule by one 20 mm tenon in
# a mortise (0.15 mm clearance): the eye vane with a 1.2 mm wide sighting slit 80 mm long, the
# object vane with a 16 x 80 mm window and 1.5 mm holes 8 mm above and below it on the centre
# line for the sighting hair; both from 20 mm above the rule. "EYE" and "OBJECT" engraved
# beside the openings, upright.

import "std/joints.aidl"

units mm
ply = 6 mm
thickness ply

rule_l = 300 mm
rule_w = 50 mm
scale_l = 250 mm
vane_w = 40 mm
vane_h = 120 mm
vane_x = 135 mm
tenon = 20 mm
sight_mid = 60 mm
sight_len = 80 mm

def vane(eye=true) -> solid {
    body = RoundedRectangle(bottom_left=(-vane_w / 2, -ply), width=vane_w, height=vane_h + ply,
                            corner_radii=[8, 8, 0, 0])
    Fixed(body)
    foot = tab_and_slot(part="tab", length=vane_w, thickness=ply, tabs=1, tab=tenon, screw=0,
                        rotation=180 deg, cx=0, cy=-ply)
    if eye {
        hole sight { s = Slot(center=(0, sight_mid), length=sight_len, width=1.2, rotation=90 deg) }
        drawing label { word = Text("EYE", position=(13, sight_mid), size=4, valign="middle", rotation=90 deg) }
    } else {
        hole sight { s = Rectangle(center=(0, sight_mid), width=16, height=sight_len) }
        hole hair_top { c = Circle(center=(0, sight_mid + sight_len / 2 + 8), diameter=1.5) }
        hole hair_bottom { c = Circle(center=(0, sight_mid - sight_len / 2 - 8), diameter=1.5) }
        drawing label { word = Text("OBJECT", position=(14, sight_mid), size=4, valign="middle", rotation=90 deg) }
    }
}

assembly alidade {
    solid rule {
        body = Rectangle(center=(0, 0), width=rule_l, height=rule_w)
        Fixed(body)
        seat_eye = tab_and_slot(part="slot", length=vane_w, thickness=ply, tabs=1, tab=tenon, screw=0,
                                clearance=0.15, rotation=90 deg, cx=-vane_x, cy=0)
        seat_object = tab_and_slot(part="slot", length=vane_w, thickness=ply, tabs=1, tab=tenon, screw=0,
                                   clearance=0.15, rotation=90 deg, cx=vane_x, cy=0)
        hole compass { c = Circle(center=(60, 10), diameter=20.2) }
        drawing scale {
            for i in range(251) {
                tick = Line((-scale_l / 2 + i * 1 mm, -rule_w / 2),
                            (-scale_l / 2 + i * 1 mm, -rule_w / 2 + (6 mm if i % 10 == 0 else (3.5 mm if i % 5 == 0 else 2 mm))))
            }
            for k in range(26) {
                num = Text(str(k), position=(-scale_l / 2 + k * 10 mm, -rule_w / 2 + 7.5 mm), size=3)
            }
        }
        drawing title { words = Text("CLASS 5B ALIDADE", position=(-60, 10), size=5, valign="middle") }

        assert body.width == 300 mm and body.height == 50 mm, "300 x 50 rule"
        assert len(scale.tick) == 251 and scale.tick[250].start.x - scale.tick[0].start.x == 250 mm, "a 250 mm scale"
        assert scale.tick[0].start.x - body.bb.left == 25 mm, "the scale centred"
        assert scale.tick[10].length == 6 mm and scale.tick[5].length == 3.5 mm and scale.tick[1].length == 2 mm, "tick lengths"
        assert distance(title, compass) >= 5 mm and distance(title, scale) >= 2 mm, "title clear"
        assert distance(compass, scale) >= 2 mm, "compass clear of the numbers"
        assert seat_object.slot[0].bb.center.x - seat_eye.slot[0].bb.center.x == 270 mm, "vanes 135 mm either side"
        assert seat_eye.slot[0].bb.width == ply + 0.15 mm and seat_eye.slot[0].bb.height == tenon + 0.15 mm, "mortise fits the tenon"
    }
    eye = vane(eye=true)
    object = vane(eye=false)

    # flat: the vanes above the rule
    Above(eye, rule, gap=10)
    AlignLeft(eye, rule)
    RightOf(object, eye, gap=10)
    AlignBottom(object, eye)

    # assembled: vanes upright in their mortises, engraved faces outwards
    Place(rule, position=(0, 0, 0))
    Place(eye, position=(-vane_x + ply / 2, 0, ply), face="left", up="up")
    Place(object, position=(vane_x - ply / 2, 0, ply), face="right", up="up")

    assert eye.body.bb.top == 120 mm and eye.body.bb.width == 40 mm, "vanes 40 wide, 120 above the rule"
    assert eye.sight.s.width == 1.2 mm and eye.sight.s.length == 80 mm, "1.2 x 80 slit"
    assert object.sight.s.width == 16 mm and object.sight.s.height == 80 mm, "16 x 80 window"
    assert eye.sight.s.bb.bottom == 20 mm and object.sight.s.bb.bottom == 20 mm, "sights from 20 mm up"
    assert object.hair_top.c.center.y - object.sight.s.bb.top == 8 mm, "hair hole 8 mm above"
    assert object.sight.s.bb.bottom - object.hair_bottom.c.center.y == 8 mm, "hair hole 8 mm below"
    assert eye.sight.s.center.x == object.sight.s.center.x, "slit and window on one sight line"
    assert distance(eye.label, eye.sight) >= 2 mm and distance(object.label, object.sight) >= 2 mm, "labels clear"
}
