# Request (pets): a wall caddy for a dog's grooming kit, 6 mm ply. A back plate 260 x 180
# (R10 corners) on two keyholes (8 mm head, 4 mm slot 10 long, up) 100 mm either side of
# the centre, 20 mm below the top. A shelf 260 wide standing out 70 mm from the plate's
# face, its top 24 mm below the plate's centre, glued into the plate by three 30 mm through
# tenons and carried by two triangular brackets (55 mm legs under the shelf and down the
# plate, the two tips clipped 8 mm) at 100 mm either side of the centre, each with one 20 mm
# tenon into the plate and one into the shelf. In the shelf: two brush slots 45 x 16 and a
# comb slot 60 x 6, all 35 mm in from the front edge. Above the shelf the dog's name "MILO"
# engraved filled (bold sans, 26 mm capitals) with "GROOMING KIT" under it (8 mm), and a
# paw print (pad and four toes, 22 mm wide) engraved filled each side of the name.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

ply = 6 mm
plate_w = 260 mm
plate_h = 180 mm
shelf_d = 70 mm
shelf_top = -24 mm     # the shelf's top face, in the plate's y (0 = its centre)
leg = 55 mm
clip = 8 mm
bracket_x = 100 mm

def bracket() -> solid {
    # x = 0: its back tenon's tip (the plate's back face), running out from the wall;
    # y = 0: its top tenon's tip (the shelf's top face)
    body = Polygon([(0, 0), (ply + leg, 0), (ply + leg, -clip), (clip, -ply - leg),
                    (0, -ply - leg)])
    top_t = tab_and_slot(part="tab", length=ply + leg, thickness=ply, tabs=1, tab=20 mm,
                         screw=0, cx=(ply + leg) / 2, cy=0 mm)
    back_t = tab_and_slot(part="tab", length=ply + leg, thickness=ply, tabs=1, tab=20 mm,
                          screw=0, rotation=90 deg, cx=0 mm, cy=-(ply + leg) / 2)
}

def paw() -> drawing {
    pad = Ellipse(center=(0, -4), rx=8, ry=6.5, fill=true)
    toe_a = Circle(center=(-8, 5.5), radius=3, fill=true)
    toe_b = Circle(center=(-3, 10), radius=3, fill=true)
    toe_c = Circle(center=(3, 10), radius=3, fill=true)
    toe_d = Circle(center=(8, 5.5), radius=3, fill=true)
}

assembly grooming_caddy {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h,
                                corner_radius=10)
        for i in range(2) {
            hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                           cx=(i * 2 - 1) * bracket_x, cy=plate_h / 2 - 20 mm)
            # the brackets' back tenons: a vertical mortise where each bracket stands
            b_mort = tab_and_slot(part="slot", length=ply + leg, thickness=ply, tabs=1,
                                  tab=20 mm, screw=0, rotation=90 deg,
                                  cx=(i * 2 - 1) * bracket_x,
                                  cy=shelf_top - (ply + leg) / 2)
        }
        # the shelf's tenons: the shelf's middle is half a ply under its top
        s_mort = tab_and_slot(part="slot", length=plate_w, thickness=ply, tabs=3, tab=30 mm,
                              screw=0, cx=0 mm, cy=shelf_top - ply / 2)
        drawing name {
            word = Text("MILO", position=(0, 40), size=26, font="sans:Bold",
                        valign="middle", fill=true)
            sub = Text("GROOMING KIT", position=(0, 12), size=8, font="sans:Bold",
                       valign="middle", fill=true)
        }
        paw_l = paw()
        paw_r = paw()
        AlignCenterY(paw_l, name.word)
        AlignCenterY(paw_r, name.word)
        paw_l.bb.center_x == -75 mm
        paw_r.bb.center_x == 75 mm
    }

    solid shelf {
        # y = 0: the plate's front face; the back tenons reach ply into it, y = ply
        body = Rectangle(bottom_left=(-plate_w / 2, -shelf_d), width=plate_w,
                         height=shelf_d + ply)
        ten = tab_and_slot(part="tab", length=plate_w, thickness=ply, tabs=3, tab=30 mm,
                           screw=0, cx=0 mm, cy=ply)
        for i in range(2) {
            # the brackets' top tenons: a mortise along y where each bracket stands
            b_mort = tab_and_slot(part="slot", length=ply + leg, thickness=ply, tabs=1,
                                  tab=20 mm, screw=0, rotation=90 deg,
                                  cx=(i * 2 - 1) * bracket_x, cy=ply - (ply + leg) / 2)
        }
        # FIX after the first valid program: W0508 was right, brush_a ran into the left
        # bracket's mortise; the three slots moved 20 / 20 / 15 mm to the right
        hole tools {
            brush_a = Slot(center=(-55, -35), length=45, width=16)
            brush_b = Slot(center=(0, -35), length=45, width=16)
            comb = Slot(center=(60, -35), length=60, width=6)
        }
    }

    left_b = bracket()
    right_b = bracket()

    # flat: shelf under the plate, brackets right of the plate
    Below(shelf, plate, gap=10)
    AlignLeft(shelf, plate)
    RightOf(left_b, plate, gap=10)
    AlignTop(left_b, plate)
    RightOf(right_b, left_b, gap=10)
    AlignTop(right_b, plate)

    # 3D: plate's back face at y = ply, its face to the front
    Place(plate, position=(0, ply, 0), face="front", up="up")
    Place(shelf, position=(0, 0, shelf_top - ply), face="up", up="back")
    Place(left_b, position=(-bracket_x + ply / 2, ply, shelf_top), face="left", up="up")
    Place(right_b, position=(bracket_x + ply / 2, ply, shelf_top), face="left", up="up")

    assert plate.body.bb.width == 260 mm and plate.body.bb.height == 180 mm, "plate size"
    assert plate.hang[1].head_hole.center.x - plate.hang[0].head_hole.center.x == 200 mm,
        "keyholes 100 either side"
    assert plate.body.bb.top - plate.hang[0].head_hole.center.y == 20 mm, "keyholes 20 down"
    assert shelf.body.bb.height - ply == 70 mm, "shelf stands out 70"
    assert len(shelf.ten.gap) == 4, "three tenons: four gaps"
    assert left_b.body.bb.width - ply == 55 mm, "bracket leg 55"
    assert shelf.tools.brush_a.length == 45 mm and shelf.tools.brush_a.width == 16 mm,
        "brush slot 45 x 16"
    assert shelf.tools.comb.length == 60 mm and shelf.tools.comb.width == 6 mm, "comb slot"
    assert shelf.tools.brush_a.center.y - shelf.body.bb.bottom == 35 mm, "35 from the front"
    assert distance(shelf.tools, shelf.b_mort[1]) >= 3 mm, "comb clear of the bracket"
    assert distance(shelf.tools, shelf.b_mort[0]) >= 3 mm, "brush clear of the bracket"
    assert plate.name.word.size == 26 mm, "26 mm name"
    assert plate.paw_r.bb.width <= 22 mm + 0.5 mm, "paw 22 wide"
    assert distance(plate.paw_r, plate.name.word) >= 5 mm, "paw clear of the name"
    assert plate.name.bb.bottom - (plate.body.bb.center_y + shelf_top) >= 5 mm,
        "words above the shelf"
}
