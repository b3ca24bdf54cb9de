# Request: a wall saddle rack for the tack room, cut from 9 mm birch ply, glued and screwed.
# A back plate 200 wide x 300 tall, fixed with four 5 mm countersunk wood screws (5.5 mm
# holes, 11 mm heads) 20 mm in from each corner. Two ribs 100 mm apart (centres) project
# 410 mm from the wall: straight top 20 mm below the plate's top, 250 mm tall at the wall,
# 50 mm tall at the front (front top corner R15), a concave lower edge; each rib is glued
# into the plate by three 40 mm tabs. Three arched formers (240 mm wide, 110 mm tall, a
# 120 x 70 mm oval lightening hole) sit across the ribs 100, 230 and 360 mm out from the
# wall, cross-halved 20 mm + 20 mm (0.2 mm clearance). The horse's name "BRAMBLE" is
# engraved filled on the front former, which has no lightening hole.

units mm
thickness 9 mm
import "std/joints.aidl"

T = 9 mm
rib_len = 410 mm + T     # tab tips flush with the plate's back face
rib_h = 250 mm
rib_gap = 100 mm         # between the ribs' middles
rib_top = 280 mm         # the ribs' top edge on the plate (20 below its 300 mm top)
former_at = [100 mm, 230 mm, 360 mm]
halve = 20 mm

def rib() -> solid {
    # frame: x from the plate's back face outward, y = 0 the top edge
    top = Line((0, 0), (rib_len, 0))
    nose = Line((rib_len, 0), (rib_len, -50))
    belly = Arc(start=(rib_len, -50), through=(169.3, -120.9), end=(0, -rib_h))
    back = Line((0, -rib_h), (0, 0))
    Fillet(top.end, 15)
    tabs = tab_and_slot(part="tab", length=rib_h, thickness=T, tabs=3, tab=40 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=-rib_h / 2)
    for i in range(3) {
        seat = cross_halving(depth=halve, thickness=T, clearance=0.2 mm,
                             cx=former_at[i], cy=0 mm)
    }
    Rigid(self)
}

def former(lighten=true) -> solid {
    # frame: bottom edge on y = 0, centred on x = 0
    bottom = Line((-120, 0), (120, 0))
    right = Line((120, 0), (120, 30))
    crown = Arc(start=(120, 30), through=(0, 110), end=(-120, 30))
    left = Line((-120, 30), (-120, 0))
    if lighten {
        hole oval { e = Ellipse(center=(0, 50), rx=60, ry=35) }
    }
    left_seat = cross_halving(depth=halve, thickness=T, clearance=0.2 mm, rotation=180 deg,
                              cx=-rib_gap / 2, cy=0 mm)
    right_seat = cross_halving(depth=halve, thickness=T, clearance=0.2 mm, rotation=180 deg,
                               cx=rib_gap / 2, cy=0 mm)
    Rigid(self)
}

assembly saddle_rack {
    solid plate {
        body = Rectangle(bottom_left=(-100, 0), width=200, height=300)
        hole screw { c = Circle(center=(-80, 20), diameter=5.5) }
        screws = CornerPattern(screw, body, inset=20)
        Countersink(screws, diameter=11)
        left_mortise = tab_and_slot(part="slot", length=rib_h, thickness=T, tabs=3, tab=40 mm,
                                    screw=0, rotation=90 deg, cx=-rib_gap / 2,
                                    cy=rib_top - rib_h / 2)
        right_mortise = tab_and_slot(part="slot", length=rib_h, thickness=T, tabs=3, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=rib_gap / 2,
                                     cy=rib_top - rib_h / 2)
    }
    left_rib = rib()
    right_rib = rib()
    back_former = former()
    middle_former = former()
    front_former = former(lighten=false)
    drawing name {
        t = Text("BRAMBLE", position=(0, 0), size=18, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CutInto(name, front_former)
    AlignCenterX(name.t.position, front_former)
    name.t.position.y == front_former.bb.bottom + 50 mm

    # flat layout
    RightOf(left_rib, plate, gap=10)
    AlignTop(left_rib, plate)
    Below(right_rib, left_rib, gap=10)
    AlignLeft(right_rib, left_rib)
    Below(back_former, plate, gap=10)
    AlignLeft(back_former, plate)
    RightOf(middle_former, back_former, gap=10)
    AlignTop(middle_former, back_former)
    RightOf(front_former, middle_former, gap=10)
    AlignTop(front_former, back_former)

    # 3D: the plate on the wall (back face y = 0), ribs outward (-y), formers across them
    Place(plate, position=(0, 0, 0), face="front", up="up")
    Place(left_rib, position=(-rib_gap / 2 + T / 2, 0, rib_top), face="left", up="up")
    Place(right_rib, position=(rib_gap / 2 + T / 2, 0, rib_top), face="left", up="up")
    Place(back_former, position=(0, -former_at[0] + T / 2, rib_top - 2 * halve), face="front", up="up")
    Place(middle_former, position=(0, -former_at[1] + T / 2, rib_top - 2 * halve), face="front", up="up")
    Place(front_former, position=(0, -former_at[2] + T / 2, rib_top - 2 * halve), face="front", up="up")

    # the request's numbers
    assert plate.body.width == 200 mm and plate.body.height == 300 mm, "plate 200 x 300"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - plate.body.bb.left == 20 mm, "screws 20 in"
    assert screws[0].c.center.y - plate.body.bb.bottom == 20 mm, "screws 20 in"
    assert left_rib.bb.width - T == 410 mm, "ribs project 410"
    assert left_rib.back.length == 250 mm, "ribs 250 tall at the wall"
    assert left_rib.nose.length == 50 mm, "ribs 50 tall at the front"
    assert 300 mm - rib_top == 20 mm, "rib tops 20 below the plate top"
    assert back_former.bb.width == 240 mm and front_former.bb.height == 110 mm, "formers 240 x 110"
    assert len(former_at) == 3, "three formers"
    # formers clear the wall and stay on the ribs
    assert former_at[0] - T / 2 - T > 50 mm, "back former clear of the plate"
    assert former_at[2] + T / 2 < rib_len - 15 mm, "front former on the rib's straight top"
}
