# Request (toys): a hob for my daughter's play kitchen, 6 mm ply.
# - Top plate 420 x 300 mm, 15 mm corners, with four burners engraved: two large (ring
#   120 mm across, a filled 60 mm cap, eight grate bars between) at back left and front
#   right, two small (90 mm ring, 44 mm cap) at back right and front left; burner centres
#   105 mm each side of the middle, 45 mm behind and 65 mm in front of the plate's centre.
#   "MIA'S KITCHEN" in filled 12 mm bold letters along the back, centred 130 mm behind the centre.
# - A front apron 400 x 80 mm standing under the plate's front edge, glued into it with three
#   40 mm tabs whose mortises are 13 mm (centre) in from the plate's front edge.
# - Four knobs 46 mm across with eight 10 mm finger scallops, an 8.2 mm bore for a glued
#   8 mm dowel and an engraved pointer; the dowels turn in 8.5 mm holes in the apron, 100 mm
#   apart, 10 mm below the apron's middle. Round each knob hole a dial of six ticks numbered
#   0 to 5, 0 at the left, 5 at the right, over the top.

import "std/joints.aidl"

t = 6 mm
thickness t

def dial_angle(k) = 180 deg - k * 36 deg

def burner(x=0 mm, y=0 mm, outer=120 mm, inner=60 mm) -> drawing {
    ring = Circle(center=(x, y), diameter=outer)
    cap = Circle(center=(x, y), diameter=inner, fill=true)
    for k in range(8) {
        bar = Line((x + (inner / 2 + 4 mm) * cos(k * 45 deg), y + (inner / 2 + 4 mm) * sin(k * 45 deg)),
                   (x + (outer / 2 - 4 mm) * cos(k * 45 deg), y + (outer / 2 - 4 mm) * sin(k * 45 deg)))
    }
}

def knob() -> solid {
    disc = Circle(center=(0, 0), diameter=46)
    hole grip {
        for k in range(8) {
            s = Circle(center=(23 * cos(k * 45 deg + 22.5 deg), 23 * sin(k * 45 deg + 22.5 deg)),
                       diameter=10)
        }
    }
    hole bore { b = Circle(center=(0, 0), diameter=8.2) }
    drawing mark { pointer = Line((0, 9), (0, 19)) }
    Fillet(1.5)
}

assembly hob {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=420, height=300, corner_radius=15)
        back_left = burner(x=-105 mm, y=45 mm, outer=120 mm, inner=60 mm)
        front_right = burner(x=105 mm, y=-65 mm, outer=120 mm, inner=60 mm)
        back_right = burner(x=105 mm, y=45 mm, outer=90 mm, inner=44 mm)
        front_left = burner(x=-105 mm, y=-65 mm, outer=90 mm, inner=44 mm)
        drawing name {
            word = Text("MIA'S KITCHEN", position=(0, 130), size=12, font="sans:Bold",
                        valign="middle", fill=true)
        }
        slots = tab_and_slot(part="slot", length=400 mm, thickness=t, tabs=3, tab=40 mm,
                             screw=0, cx=0 mm, cy=-137 mm)
    }

    # the apron, drawn with its tab tips (the plate's top face) at y = 40
    solid apron {
        body = Rectangle(center=(0, 0), width=400, height=80)
        tabs = tab_and_slot(part="tab", length=400 mm, thickness=t, tabs=3, tab=40 mm,
                            screw=0, cx=0 mm, cy=40 mm)
        hole holes {
            for i in range(4) {
                h = Circle(center=(i * 100 - 150, -10), diameter=8.5)
            }
        }
        drawing dials {
            for i in range(4) {
                for k in range(6) {
                    tick = Line((i * 100 - 150 + 27 * cos(dial_angle(k)), -10 + 27 * sin(dial_angle(k))),
                                (i * 100 - 150 + 31 * cos(dial_angle(k)), -10 + 31 * sin(dial_angle(k))))
                    num = Text(str(k), position=(i * 100 - 150 + 36 * cos(dial_angle(k)),
                                                 -10 + 36 * sin(dial_angle(k))),
                               size=5, valign="middle")
                }
            }
        }
    }

    for i in range(4) {
        kn = knob()
        # on the apron's front face, on its hole (apron frame y = -10 is 30 above the floor)
        Place(kn, position=((i * 100 - 150) * 1 mm, -140 mm, 30 mm), face="front", up="up")
    }

    # 3D: the plate's top face 80 above the floor, the apron under its front edge
    Place(top, position=(0, 0, 74 mm))
    Place(apron, position=(0, -134 mm, 40 mm), face="front", up="up")

    # flat layout for cutting
    Below(apron, top, gap=6 mm)
    AlignCenterX(apron, top)
    RightOf(kn[0], top, gap=6 mm)
    AlignTop(kn[0], top)
    for i in range(1, 4) {
        Below(kn[i], kn[i - 1], gap=6 mm)
        AlignLeft(kn[i], kn[0])
    }

    # the request's numbers
    assert top.body.width == 420 mm and top.body.height == 300 mm, "plate 420 x 300"
    assert apron.body.width == 400 mm and apron.body.height == 80 mm, "apron 400 x 80"
    assert top.back_left.ring.diameter == 120 mm and top.back_left.cap.diameter == 60 mm, "large burner"
    assert top.back_right.ring.diameter == 90 mm and top.back_right.cap.diameter == 44 mm, "small burner"
    assert top.front_right.ring.center.x - top.back_left.ring.center.x == 2 * 105 mm, "105 each side"
    assert top.back_left.ring.center.y - top.body.center.y == 45 mm, "back burners 45 behind"
    assert top.body.center.y - top.front_left.ring.center.y == 65 mm, "front burners 65 in front"
    assert top.name.word.position.y - top.body.center.y == 130 mm, "name 130 behind the centre"
    assert top.slots.slot[0].bb.center_y - top.body.bb.bottom == 13 mm, "mortises 13 in"
    assert len(top.slots.slot) == 3 and top.slots.slot[0].bb.width == 40 mm, "three 40 mm tabs"
    assert distance(top.front_right, top.slots) >= 5 mm, "burner clear of the mortises"
    assert distance(top.name, top.back_left) >= 3 mm, "name clear of the burner"
    assert len(kn) == 4 and kn[0].disc.diameter == 46 mm, "four 46 mm knobs"
    assert kn[0].grip.s[0].diameter == 10 mm and len(kn[0].grip.s) == 8, "eight 10 mm scallops"
    assert apron.holes.h[0].diameter > kn[0].bore.b.diameter, "the dowel turns in the apron"
    assert apron.holes.h[1].center.x - apron.holes.h[0].center.x == 100 mm, "knobs 100 apart"
    assert apron.body.center.y - apron.holes.h[0].center.y == 10 mm, "holes 10 below the middle"
    assert apron.dials.bb.top <= apron.body.bb.top - t - 2 mm, "dials below the plate"
    assert 36 mm - 5 mm / 2 > 46 mm / 2 + 2 mm, "dial numbers clear of the knob"
}
