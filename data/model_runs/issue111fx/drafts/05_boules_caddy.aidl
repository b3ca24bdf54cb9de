# Request: a carrier for my set of three petanque boules (74 mm) and the jack (30 mm), in 6 mm
# birch ply, glued tab-and-slot, carried by a 20 mm dowel handle.
# - Base: 322 x 110 mm, corners R10, on the ground.
# - Two end panels 110 wide, standing 150 mm above the base, round-topped (a full R55
#   semicircle), two 25 mm tabs each into the base, a 20.5 mm hole for the dowel 135 mm above
#   the base, "PETANQUE" with its accent (PÉTANQUE) engraved filled on the outside, at most
#   90 mm wide.
# - Cradle plate between the end panels, 290 mm clear between them, 110 wide, its underside
#   40 mm above the base, two 25 mm tabs at each end through the end panels: three 70 mm holes
#   at 80 mm pitch for the boules (they rest in them) and a 26 mm hole for the jack.
# - The dowel must leave at least 25 mm over a resting boule so one lifts out.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
inner = 290 mm        # clear length between the end panels
plate_z = 40 mm       # the cradle's underside above the base
dowel_z = 135 mm      # the dowel's centre above the base
boule_d = 74 mm
ring_d = 70 mm

def end_panel() -> solid {
    body = RoundedRectangle(corner=(-55, 0), opposite=(55, t + 150), corner_radii=[55, 55, 0, 0])
    feet = tab_and_slot(part="tab", length=110, thickness=t, tabs=2, tab=25, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    cradle = tab_and_slot(part="slot", length=110, thickness=t, tabs=2, tab=25, screw=0,
                          cx=0, cy=t + plate_z + t / 2)
    hole dowel { c = Circle(center=(0, t + dowel_z), diameter=20.5) }
    drawing word {
        w = Text("PÉTANQUE", position=(0, 95), size=12, font="sans:Bold", valign="middle",
                 max_width=90, fill=true)
    }
}

assembly caddy {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=322, height=110, corner_radius=10)
        left_slots = tab_and_slot(part="slot", length=110, thickness=t, tabs=2, tab=25, screw=0,
                                  rotation=90 deg, cx=-(inner / 2 + t / 2), cy=0)
        right_slots = tab_and_slot(part="slot", length=110, thickness=t, tabs=2, tab=25, screw=0,
                                   rotation=90 deg, cx=inner / 2 + t / 2, cy=0)
    }

    solid cradle {
        body = Rectangle(center=(0, 0), width=inner + 2 * t, height=110)
        left_tabs = tab_and_slot(part="tab", length=110, thickness=t, tabs=2, tab=25, screw=0,
                                 rotation=90 deg, cx=-(inner / 2 + t), cy=0)
        right_tabs = tab_and_slot(part="tab", length=110, thickness=t, tabs=2, tab=25, screw=0,
                                  rotation=-90 deg, cx=inner / 2 + t, cy=0)
        hole boules {
            for i in range(3) {
                c = Circle(center=(-100 + i * 80, 0), diameter=ring_d)
            }
        }
        hole jack { c = Circle(center=(115, 0), diameter=26) }
    }

    left = end_panel()
    right = end_panel()

    # flat on the sheet
    Below(cradle, base, gap=10)
    AlignLeft(cradle, base)
    Below(left, cradle, gap=10)
    AlignLeft(left, cradle)
    RightOf(right, left, gap=10)
    AlignTop(right, left)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(cradle, position=(0, 0, t + plate_z))
    Place(right, position=(inner / 2, 0, 0), face="right", up="up")
    Place(left, position=(-inner / 2, 0, 0), face="left", up="up")

    # the request's numbers
    assert base.plate.width == 322 mm and base.plate.height == 110 mm, "base 322 x 110"
    assert left.body.bb.height == 150 mm + 6 mm, "end panels 150 above the 6 mm base"
    assert len(cradle.boules.c) == 3, "three boules"
    assert cradle.boules.c[0].diameter == 70 mm, "70 mm rests"
    assert cradle.boules.c[1].center.x - cradle.boules.c[0].center.x == 80 mm, "80 mm pitch"
    assert cradle.jack.c.diameter == 26 mm, "26 mm jack hole"
    assert cradle.jack.c.diameter < 30 mm, "the jack rests in it"
    assert distance(cradle.boules, cradle.jack) >= 5 mm, "wood between the jack and a boule"
    assert cradle.body.bb.width - 2 * 6 mm == 290 mm, "290 mm between the end panels"
    assert left.dowel.c.diameter == 20.5 mm, "20.5 mm dowel hole"
    assert left.dowel.c.center.y - left.body.bb.bottom == 6 mm + 135 mm, "dowel 135 above the base"
    assert left.word.bb.width <= 90 mm, "PETANQUE at most 90 wide"
    assert distance(left.word, left.dowel) >= 5 mm, "word clear of the dowel hole"
    assert distance(left.word, left.cradle) >= 5 mm, "word clear of the cradle's slots"
    # a resting boule: its centre sqrt(R^2 - r^2) over the cradle's top face
    assert (135 mm - 20.5 mm / 2) -
        (40 mm + 6 mm + sqrt((74 mm / 2) ** 2 - (70 mm / 2) ** 2) + 74 mm / 2) >= 25 mm,
        "a boule lifts out under the dowel"
    assert (70 mm / 2 + 70 mm / 2) + 5 mm <= 80 mm, "wood between the rests"
}
