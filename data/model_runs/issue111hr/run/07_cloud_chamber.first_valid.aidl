# Request (science): a dry-ice cloud chamber for a school science club, 3 mm clear acrylic. An
# open-bottomed finger-jointed box 200 x 150 x 120 mm outside (10 mm fingers) that stands upside
# down on a black aluminium plate over dry ice, so its solid face is the viewing window on top:
# - the window (the box's bottom panel) has a 10 mm filling hole for the alcohol, its centre
#   20 mm in from the left and back edges (left, back, front: as the box is named upright);
# - the back wall carries a 10 mm grid engraved over 160 x 80 mm in its middle to judge the
#   tracks' lengths;
# - the left wall has a 6 mm hole for the LED strip's cable, 15 mm from its open edge, in the
#   middle of its depth;
# - the front wall says "CLOUD CHAMBER" (10 mm, bold, filled), its middle 20 mm from the window
#   edge, and "FILL: 99% ISOPROPYL ALCOHOL" (4 mm strokes) 34 mm from it, both reading the right
#   way up when the box stands upside down.
# A locating frame from the same sheet, 250 x 200 mm with 8 mm corners and a 202 x 152 mm
# opening (1 mm round the box), lies on the plate round the box's open edge; its border says
# "DRY ICE: WEAR GLOVES" (4 mm strokes) centred 12 mm above its bottom edge.

units mm
thickness 3 mm
import "std/joints.aidl"

assembly chamber {
    box = finger_box(length=200 mm, depth=150 mm, height=120 mm, thickness=3 mm, finger=10 mm,
                     closed=false)

    hole fill { c = Circle(center=(0, 0), diameter=10) }
    fill.c.center.x == box.bottom.bb.left + 20
    fill.c.center.y == box.bottom.bb.top - 20
    CutInto(fill, box.bottom)

    drawing grid {
        for i in range(17) {
            v = Line((-80 + 10 * i, -40), (-80 + 10 * i, 40))
        }
        for j in range(9) {
            h = Line((-80, -40 + 10 * j), (80, -40 + 10 * j))
        }
    }
    CenterInside(grid, box.back)
    CutInto(grid, box.back)

    hole cable { c = Circle(center=(0, 0), diameter=6) }
    cable.c.center.x == box.left.bb.left + 15
    cable.c.center.y == box.left.bb.center_y
    CutInto(cable, box.left)

    # upside down: turned 180 deg, and measured from the front's bottom edge (the window's)
    drawing words {
        big = Text("CLOUD CHAMBER", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                   rotation=180, fill=true)
        small = Text("FILL: 99% ISOPROPYL ALCOHOL", position=(0, 14), size=4, valign="middle",
                     rotation=180)
    }
    AlignCenterX(words, box.front)
    words.big.position.y == box.front.bb.bottom + 20
    CutInto(words, box.front)

    solid frame {
        body = RoundedRectangle(center=(0, 0), width=250, height=200, corner_radius=8)
        hole opening { r = Rectangle(center=(0, 0), width=202, height=152) }
        drawing note { t = Text("DRY ICE: WEAR GLOVES", position=(0, -100 + 12), size=4, valign="middle") }
    }
    RightOf(frame, box, gap=10)
    AlignTop(frame, box)
    # in 3D: round the open rim (the box is shown standing the right way up)
    Place(frame, position=(0, 0, 120 - 3))

    # the request's numbers
    assert fill.c.center.x - box.bottom.bb.left == 20 mm and box.bottom.bb.top - fill.c.center.y == 20 mm,
        "fill hole 20 mm in from the left and back edges"
    assert len(grid.v) == 17 and len(grid.h) == 9, "grid lines every 10 mm over 160 x 80"
    assert grid.bb.width == 160 mm and grid.bb.height == 80 mm, "grid 160 x 80"
    assert cable.c.center.x - box.left.bb.left == 15 mm, "cable hole 15 mm from the open edge"
    assert words.big.position.y - box.front.bb.bottom == 20 mm, "title 20 mm from the window edge"
    assert words.small.position.y - box.front.bb.bottom == 34 mm, "fill note 34 mm from the window edge"
    assert words.bb.width <= box.front.bb.width - 20 mm, "the words fit the front"
    assert frame.opening.r.width == box.length + 2 mm and frame.opening.r.height == box.depth + 2 mm,
        "frame opening 1 mm round the box"
    assert frame.note.t.position.y - frame.body.bb.bottom == 12 mm, "glove note 12 mm up"
    assert frame.note.bb.top <= frame.opening.r.bb.bottom - 3 mm, "glove note on the border"
}
