# Request: a drying rack for my makeup brushes, so they dry bristles-down after washing and the
# water can't run into the ferrules. 5 mm clear acrylic (it lives by the bathroom sink).
# - a top plate 260 x 70 mm with 8 mm rounded corners and a row of 8 keyhole openings, 27 mm
#   apart, centred: the brush handle drops through the round entry (handle + 4 mm) and slides
#   14 mm back into a slot as wide as the handle, where the taper holds it. Handles: four of
#   8 mm, three of 11 mm, one of 15 mm. Each handle size engraved under its opening.
# - two legs, 90 mm wide at the foot, 70 mm at the top, that hold the plate's top face 185 mm
#   above the counter, each with a 36 mm wide stadium window 100 mm long for lightness;
#   each leg stands in two 15 mm tabs through slots in the plate, 115 mm either side of centre.
# - a stretcher 30 mm tall between the legs, 28 mm behind the openings' line of centres
#   (behind the hanging brush heads), with a flush through-tenon 18 mm tall into each leg.

units mm
thickness 5 mm
import "std/joints.aidl"
import "std/plates.aidl"

T = 5 mm
D = [8, 8, 8, 8, 11, 11, 11, 15]   # handle sizes, mm
PITCH = 27 mm
LEG_X = 115 mm       # the legs' middle planes from the centre
LEG_H = 185 mm       # floor to the tabs' tips (the plate's top face)
BACK = 28 mm         # the stretcher's middle plane behind the openings' line
STRETCH_Z = 35 mm    # the stretcher's middle height

def leg() -> solid {
    # side view: x = depth (front -x), y = height above the counter
    body = Trapezoid(center=(0, LEG_H / 2), bottom_width=90, top_width=70, height=LEG_H)
    tabs = tab_and_slot(part="tab", length=70, thickness=T, tabs=2, tab=15, screw=0, cx=0, cy=LEG_H)
    hole window {
        w = Slot(center=(0, 105), length=100, width=36, rotation=90 deg)
    }
    mortise = tab_and_slot(part="slot", length=30, thickness=T, tabs=1, tab=18, screw=0,
                           rotation=90 deg, cx=BACK, cy=STRETCH_Z)
}

assembly brush_rack {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=260, height=70, corner_radius=8)
        for i in range(8) {
            k = keyhole(head=D[i] + 4, slot_width=D[i], length=14, direction=90 deg,
                        cx=(i - 3.5) * PITCH, cy=-10)
        }
        left_slots = tab_and_slot(part="slot", length=70, thickness=T, tabs=2, tab=15, screw=0,
                                  rotation=90 deg, cx=-LEG_X, cy=0)
        right_slots = tab_and_slot(part="slot", length=70, thickness=T, tabs=2, tab=15, screw=0,
                                   rotation=90 deg, cx=LEG_X, cy=0)
        drawing sizes {
            for i in range(8) {
                t = Text(str(D[i]), position=((i - 3.5) * PITCH, -26), size=3)
            }
        }
    }

    left_leg = leg()
    right_leg = leg()

    solid stretcher {
        # front view: x along the rack, y = height about its middle
        body = Rectangle(center=(0, 0), width=2 * (LEG_X - T / 2) + 2 * T, height=30)
        left_tenon = tab_and_slot(part="tab", length=30, thickness=T, tabs=1, tab=18, screw=0,
                                  rotation=90 deg, cx=-(LEG_X + T / 2), cy=0)
        right_tenon = tab_and_slot(part="tab", length=30, thickness=T, tabs=1, tab=18, screw=0,
                                   rotation=-90 deg, cx=LEG_X + T / 2, cy=0)
    }

    # on the sheet
    Below(left_leg, top, gap=10)
    AlignLeft(left_leg, top)
    RightOf(right_leg, left_leg, gap=10)
    AlignBottom(right_leg, left_leg)
    RightOf(stretcher, right_leg, gap=10)
    AlignBottom(stretcher, right_leg)

    # in 3D: x along the rack, y toward the back, z up
    Place(top, position=(0, 0, LEG_H - T))
    Place(left_leg, position=(-LEG_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_leg, position=(LEG_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(stretcher, position=(0, BACK + T / 2, STRETCH_Z), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert top.body.bb.width == 260 mm and top.body.bb.height == 70 mm, "plate 260 x 70"
    assert len(top.k) == 8, "8 openings"
    assert top.k[1].head_hole.center.x - top.k[0].head_hole.center.x == 27 mm, "27 mm apart"
    assert top.k[0].head_hole.diameter == 8 mm + 4 mm and top.k[0].slot_width == 8 mm, "8 mm handle"
    assert top.k[7].head_hole.diameter == 15 mm + 4 mm, "15 mm handle"
    assert top.k[0].length == 14 mm, "slides 14 mm back"
    assert left_leg.body.bottom_width == 90 mm and left_leg.body.top_width == 70 mm, "leg 90 / 70"
    assert left_leg.body.height == 185 mm, "plate's top face 185 above the counter"
    assert left_leg.window.w.width == 36 mm and left_leg.window.w.length == 100 mm, "window"
    assert top.right_slots.bb.center_x - top.body.bb.center_x == 115 mm, "legs 115 from centre"
    assert stretcher.body.bb.height == 30 mm, "stretcher 30 tall"
    assert left_leg.mortise.bb.center_x - left_leg.body.center.x == 28 mm, "stretcher 28 behind"
}
