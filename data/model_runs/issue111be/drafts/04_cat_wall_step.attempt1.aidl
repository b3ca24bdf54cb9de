# Request (pets): a wall-mounted cat step, 6 mm birch ply, glued and screwed to the wall.
# A 350 x 240 mm back plate (top corners rounded 20 mm) with four M5 countersunk screw holes
# (10 mm heads) 100 mm either side of the middle, 25 mm from the bottom and the top; a shelf
# 350 wide standing out 250 mm from the back plate, its top 50 mm below the back plate's top,
# front corners rounded 30 mm, joined to the back plate by two 40 mm tenons; two right-angled
# brackets under it, 150 mm either side of the middle, 190 mm deep, reaching 160 mm down
# from the shelf, each with two 30 mm tenons into the back plate and two into the shelf and a
# 50 mm round lightening hole. Four paw prints engraved filled across the shelf.

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

t = 6 mm
W = 350 mm
back_h = 240 mm
depth = 250 mm
shelf_top = back_h - 50 mm        # shelf's top, in the back plate's frame (z up)
shelf_mid = shelf_top - t / 2
br_x = 150 mm                      # brackets' middle planes, either side
br_depth = 190 mm
br_low = shelf_top - t - 160 + 6   # bracket's lowest point on the back (z)

def paw(px=0 mm, py=0 mm) -> drawing {
    pad = Ellipse(center=(px, py), rx=11, ry=9, fill=true)
    t1 = Ellipse(center=(px - 14, py + 11), rx=4.5, ry=6, rotation=20 deg, fill=true)
    t2 = Ellipse(center=(px - 5, py + 18), rx=4.5, ry=6, fill=true)
    t3 = Ellipse(center=(px + 5, py + 18), rx=4.5, ry=6, fill=true)
    t4 = Ellipse(center=(px + 14, py + 11), rx=4.5, ry=6, rotation=-20 deg, fill=true)
}

solid back_plate {
    body = RoundedRectangle(bottom_left=(-W / 2, 0), width=W, height=back_h,
                            corner_radii=[20, 20, 0, 0])
    Fixed(body)
    screw = clearance_hole(size=5, cx=-100, cy=25)
    screws = CornerPattern(screw, body, inset=(W / 2 - 100 mm, 25 mm))
    Countersink(screws, diameter=10)
    shelf_slots = tab_and_slot(part="slot", length=W, thickness=t, tabs=2, tab=40, screw=0,
                               clearance=0.1, cx=0, cy=shelf_mid)
    left_slots = tab_and_slot(part="slot", length=shelf_top - t - br_low, thickness=t, tabs=2,
                              tab=30, screw=0, clearance=0.1, rotation=90 deg, cx=-br_x,
                              cy=(br_low + shelf_top - t) / 2)
    right_slots = tab_and_slot(part="slot", length=shelf_top - t - br_low, thickness=t, tabs=2,
                               tab=30, screw=0, clearance=0.1, rotation=90 deg, cx=br_x,
                               cy=(br_low + shelf_top - t) / 2)
}

solid shelf {
    # drawn from the back plate's face (y = 0: the tenons' tips) out to the front
    body = RoundedRectangle(bottom_left=(-W / 2, 0), width=W, height=depth + t,
                            corner_radii=[30, 30, 0, 0])
    Fixed(body)
    tenons = tab_and_slot(part="tab", length=W, thickness=t, tabs=2, tab=40, screw=0,
                          rotation=180 deg, cx=0, cy=0)
    left_slots = tab_and_slot(part="slot", length=br_depth, thickness=t, tabs=2, tab=30,
                              screw=0, clearance=0.1, rotation=90 deg, cx=-br_x,
                              cy=t + br_depth / 2)
    right_slots = tab_and_slot(part="slot", length=br_depth, thickness=t, tabs=2, tab=30,
                               screw=0, clearance=0.1, rotation=90 deg, cx=br_x,
                               cy=t + br_depth / 2)
    p0 = paw(px=-115, py=70)
    p1 = paw(px=-40, py=150)
    p2 = paw(px=40, py=90)
    p3 = paw(px=115, py=175)
}

def bracket() -> solid {
    # x: out from the back plate's face (tips of the back tenons at x = -t), y: up (z)
    body = Polygon([(-t, br_low), (-t, shelf_top - t), (0, shelf_top - t), (0, shelf_top),
                    (br_depth, shelf_top), (br_depth, shelf_top - 12), (12, br_low)])
    back_tenons = tab_and_slot(part="tab", length=shelf_top - t - br_low, thickness=t,
                               tabs=2, tab=30, screw=0, rotation=90 deg, cx=-t,
                               cy=(br_low + shelf_top - t) / 2)
    top_tenons = tab_and_slot(part="tab", length=br_depth, thickness=t, tabs=2, tab=30,
                              screw=0, cx=br_depth / 2, cy=shelf_top)
    hole lighten { c = Circle(center=(51, shelf_top - 51), diameter=50) }
}

assembly cat_step {
    back = back_plate
    top = shelf
    left_br = bracket()
    right_br = bracket()

    # on the sheet
    RightOf(top, back, gap=8)
    AlignBottom(top, back)
    Above(left_br, back, gap=8)
    AlignLeft(left_br, back)
    RightOf(right_br, left_br, gap=8)
    AlignBottom(right_br, left_br)

    # in 3D: wall at y = 0, back plate y 0..6 (its y -> z), shelf flat, brackets edge-on
    Place(back, position=(0, t, 0), rotation=(90 deg, 0, 0))
    Place(top, position=(0, 0, shelf_top - t))
    Place(left_br, position=(-br_x - t / 2, t, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_br, position=(br_x - t / 2, t, 0), rotation=(90 deg, 0, 90 deg))

    assert back.body.bb.width == 350 mm and back.body.bb.height == 240 mm, "back 350 x 240"
    assert len(back.screws) == 4, "four screws"
    assert back.screws[1].c.center.x - back.screws[0].c.center.x == 200 mm, "screws 100 either side"
    assert back.screws[0].c.center.y - back.body.bb.bottom == 25 mm, "screws 25 up"
    assert back.body.bb.top - back.screws[2].c.center.y == 25 mm, "screws 25 down"
    assert top.body.bb.height - t == 250 mm, "shelf stands out 250"
    assert top.body.bb.width == 350 mm, "shelf 350 wide"
    assert back_h - shelf_top == 50 mm, "shelf top 50 below the back's top"
    assert left_br.bb.width - t == 190 mm, "brackets 190 deep"
    assert shelf_top - left_br.bb.bottom == 160 mm, "brackets reach 160 down"
}
