# Request (electronics): a bench stand for a handheld multimeter (90 mm wide, 180 mm tall,
# 45 mm deep), cut from 4 mm ply. The meter lies in a V cradle tilted back 20 degrees: a
# back plate leaning at 70 degrees to the bench (140 mm long up the slope) and a ledge
# at right angles to it (50 mm deep), both 94 mm wide between two side cheeks. The plate
# and the ledge each have one tenon per side (50 mm long on the plate, 30 mm on the ledge,
# centred on their length) through a mortise in each cheek, glued. The cradle's corner is
# 50 mm behind the cheeks' front and 18 mm above the bench. Two 5 mm holes to park the
# probe tips, 15 mm below the plate's top and 12 mm in from its inner edges. Each cheek
# (130 mm deep) has "DMM" engraved filled, bold 14 mm letters, on its outer face.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
param W = 94 mm, min = 70 mm, max = 140 mm    # inner width between the cheeks
param plate_len = 140 mm, min = 100 mm, max = 200 mm
param ledge_len = 50 mm, min = 35 mm, max = 80 mm
tilt = 20 deg
cx0 = 50 mm       # the cradle corner behind the cheek's front
cy0 = 18 mm       # and above the bench
up = 90 deg - tilt          # the plate's direction, 70 deg
fwd = 180 deg - tilt        # the ledge's direction from the corner, 160 deg
plate_tab = 50 mm
ledge_tab = 30 mm

# a side cheek; s = 1: the right one, s = -1: the left one (its profile mirrored)
def cheek(s=1) -> solid {
    body = Hull(Circle(center=(s * 10, 10), radius=10), Circle(center=(s * 120, 10), radius=10),
                Circle(center=(s * 86, 112), radius=16), Circle(center=(s * 14, 36), radius=12))
    # mortise for the plate's tenon: the plate's mid-plane, at the middle of its length
    pm = (plate_len / 2 - t)
    plate_slot = tab_and_slot(part="slot", length=plate_len, thickness=t, tabs=1, tab=plate_tab,
                              screw=0, rotation=90 deg - s * tilt,
                              cx=s * (cx0 + pm * cos(up) + t / 2 * cos(tilt)),
                              cy=cy0 + pm * sin(up) - t / 2 * sin(tilt))
    # mortise for the ledge's tenon: the ledge lies under its top line from the corner
    lm = ledge_len / 2
    ledge_slot = tab_and_slot(part="slot", length=ledge_len, thickness=t, tabs=1, tab=ledge_tab,
                              screw=0, rotation=-s * tilt,
                              cx=s * (cx0 + lm * cos(fwd) - t / 2 * cos(up)),
                              cy=cy0 + lm * sin(fwd) - t / 2 * sin(up))
    drawing mark {
        word = Text("DMM", position=(s * 92, 30), size=14, font="sans:Bold", valign="middle",
                    fill=true)
    }
}

assembly stand {
    cheek_r = cheek(s=1)
    cheek_l = cheek(s=-1)

    # the back plate: local y runs up the slope from the corner line (y = 0), its bottom
    # edge t lower so that it covers the ledge's back end
    solid plate {
        body = Rectangle(bottom_left=(-W / 2 - t, -t), width=W + 2 * t, height=plate_len)
        left = tab_and_slot(part="tab", length=plate_len, thickness=t, tabs=1, tab=plate_tab,
                            screw=0, rotation=90 deg, cx=-W / 2 - t, cy=plate_len / 2 - t)
        right = tab_and_slot(part="tab", length=plate_len, thickness=t, tabs=1, tab=plate_tab,
                             screw=0, rotation=-90 deg, cx=W / 2 + t, cy=plate_len / 2 - t)
        hole probes {
            p1 = Circle(center=(-W / 2 + 12, plate_len - t - 15), diameter=5)
            p2 = Circle(center=(W / 2 - 12, plate_len - t - 15), diameter=5)
        }
    }

    # the ledge: local y from its front end (-ledge_len) back to the corner (0)
    solid ledge {
        body = Rectangle(bottom_left=(-W / 2 - t, -ledge_len), width=W + 2 * t, height=ledge_len)
        left = tab_and_slot(part="tab", length=ledge_len, thickness=t, tabs=1, tab=ledge_tab,
                            screw=0, rotation=90 deg, cx=-W / 2 - t, cy=-ledge_len / 2)
        right = tab_and_slot(part="tab", length=ledge_len, thickness=t, tabs=1, tab=ledge_tab,
                             screw=0, rotation=-90 deg, cx=W / 2 + t, cy=-ledge_len / 2)
    }

    # flat on the sheet
    RightOf(cheek_l, cheek_r, gap=8)
    AlignBottom(cheek_l, cheek_r)
    Above(plate, cheek_r, gap=8)
    AlignLeft(plate, cheek_r)
    RightOf(ledge, plate, gap=8)
    AlignBottom(ledge, plate)

    # assembled: X across, Y from front to back, Z up
    Place(cheek_r, position=(W / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(cheek_l, position=(-W / 2, 0, 0), rotation=(90 deg, 0, -90 deg))
    Place(plate, position=(0, cx0 + t * cos(tilt), cy0 - t * sin(tilt)), rotation=(up, 0, 0))
    Place(ledge, position=(0, cx0 - t * cos(up), cy0 - t * sin(up)), rotation=(-tilt, 0, 0))

    assert plate.body.bb.width - 2 * t == 94 mm, "94 mm between the cheeks"
    assert plate.body.bb.height == 140 mm and ledge.body.bb.height == 50 mm, "plate 140, ledge 50"
    assert W - 90 mm >= 2 mm, "the 90 mm meter fits"
    assert cheek_r.body.bb.width == 130 mm, "cheeks 130 mm deep"
    assert plate.body.bb.top - plate.probes.p1.center.y == 15 mm, "probe holes 15 mm below the top"
    assert plate.probes.p1.center.x - (plate.body.bb.left + t) == 12 mm, "12 mm in from the inner edge"
    assert cheek_r.mark.word.size == 14 mm, "14 mm letters"
}
