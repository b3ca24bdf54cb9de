# Request: a suggestion box for the office kitchen, 3 mm birch ply.
# - Finger-jointed box 200 wide x 150 deep x 250 tall (outside), fingers 10 mm.
# - In the lid a card slot 120 x 6 mm, in the middle.
# - On the front "SUGGESTIONS" in bold sans letters 18 mm high, engraved filled, its
#   middle 60 mm below the front's top edge, and under it "ideas welcome - no names needed"
#   engraved 6 mm high, 20 mm lower.
# - In the back an emptying opening 140 x 180 mm, in the middle, closed from outside by a
#   cover 170 x 210 mm with 6 mm rounded corners, held by 4 countersunk M3 screws (6 mm
#   heads) 10 mm in from the cover's corners, through matching M3 holes in the back (nuts
#   inside).
import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

box_w = 200 mm
box_d = 150 mm
box_h = 250 mm
open_w = 140 mm
open_h = 180 mm
cover_w = 170 mm
cover_h = 210 mm
screw_in = 10 mm

assembly suggestion_box {
    box = finger_box(length=box_w, depth=box_d, height=box_h, thickness=3 mm, finger=10 mm)

    hole card_slot {
        s = Rectangle(center=(0, 0), width=120, height=6)
    }
    CenterInside(card_slot, box.lid)
    CutInto(card_slot, box.lid)

    drawing front_words {
        title = Text("SUGGESTIONS", position=(0, 0), size=18, font="sans:Bold", valign="middle",
                     fill=true)
        sub = Text("ideas welcome - no names needed", position=(0, -20), size=6, valign="middle")
        Rigid(self)
    }
    AlignCenterX(front_words.title.position, box.front)
    front_words.title.position.y == box.front.bb.top - 60 mm
    CutInto(front_words, box.front)

    hole back_cut {
        opening = Rectangle(center=(0, 0), width=open_w, height=open_h)
        frame = Rectangle(center=(0, 0), width=cover_w - 2 * screw_in,
                          height=cover_h - 2 * screw_in, construction=true)
        h = clearance_hole(size=3)
        back_holes = CornerPattern(h, frame)
        Rigid(self)
    }
    CenterInside(back_cut, box.back)
    CutInto(back_cut, box.back)

    solid cover {
        plate = RoundedRectangle(center=(0, 0), width=cover_w, height=cover_h, corner_radius=6)
        h = clearance_hole(size=3)
        holes = CornerPattern(h, plate, inset=screw_in)
        Countersink(holes, diameter=6 mm)
    }
    RightOf(cover, box, gap=10)
    AlignBottom(cover, box)
    # 3D: on the back's outside face (the box stands on z = 0, its back at y = depth / 2)
    Place(cover, position=(0, box_d / 2, box_h / 2), face="back", up="up")

    # the request's numbers
    assert box.front.bb.width == 200 mm and box.front.bb.height == 250 mm, "box 200 wide, 250 tall"
    assert box.left.bb.height == 150 mm, "box 150 deep"
    assert card_slot.s.width == 120 mm and card_slot.s.height == 6 mm, "card slot 120 x 6"
    assert back_cut.opening.width == 140 mm and back_cut.opening.height == 180 mm, "opening 140 x 180"
    assert cover.plate.width == 170 mm and cover.plate.height == 210 mm, "cover 170 x 210"
    assert cover.holes[0].c.center.x - cover.plate.bb.left == 10 mm, "screws 10 mm in"
    assert (back_cut.back_holes[2].c.center.x - back_cut.back_holes[0].c.center.x ==
            cover.holes[2].c.center.x - cover.holes[0].c.center.x), "back holes match the cover's"
    assert box.front.bb.top - front_words.title.position.y == 60 mm, "title 60 mm below the top"
}
