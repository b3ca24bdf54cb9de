# Request (electronics): a terminal plate for the back of a DIY bookshelf speaker.
# Face plate in 3 mm black acrylic, 90 x 70 mm with 6 mm corners, on four M3 countersunk
# screws (6 mm heads) 6 mm in from each corner. Two binding posts 19 mm apart (3/4 in) on
# the plate's vertical centre line, their centres 28 mm above the bottom edge, each through
# an 8.2 mm hole with one flat 7.2 mm from the opposite side (at the top) so the post
# cannot turn. Engraved filled: "KESTREL" 9 mm tall in bold serif at the top, "8 Ω   40 W"
# 5 mm tall under it, and "+" (left post) and "−" (right post) 6 mm tall above the posts.
# Behind it a 3 mm gasket of the same outline with the same screw holes (not sunk) and a
# 60 x 36 mm window round both posts for their solder tabs.

import "std/fasteners.aidl"

thickness 3 mm

assembly terminal {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=90, height=70, corner_radius=6)
        screw = clearance_hole(size=3)
        screws = CornerPattern(screw, body, inset=6)
        Countersink(screws, diameter=6)
        hole posts {
            for i in range(2) {
                round = Circle(center=(-9.5 + i * 19, -7), diameter=8.2, construction=true)
                flat = Rectangle(center=(-9.5 + i * 19, -7.5), width=8.2, height=7.2,
                                 construction=true)
                d = Intersect(round, flat)
            }
        }
        drawing marks {
            name = Text("KESTREL", position=(0, 22), size=9, font="serif:Bold", fill=true)
            spec = Text("8 Ω   40 W", position=(0, 11), size=5, font="sans", fill=true)
            plus = Text("+", position=(-9.5, 0), size=6, font="sans:Bold", fill=true)
            minus = Text("−", position=(9.5, 0), size=6, font="sans:Bold", fill=true)
        }
        Fixed(body)
    }

    solid gasket {
        body = RoundedRectangle(center=(0, 0), width=90, height=70, corner_radius=6)
        screw = clearance_hole(size=3)
        screws = CornerPattern(screw, body, inset=6)
        hole window {
            w = Rectangle(center=(0, -7), width=60, height=36)
        }
        Fixed(body)
    }

    RightOf(gasket, plate, gap=10)
    AlignTop(gasket, plate)

    Place(gasket, position=(0, 0, 0))
    Place(plate, position=(0, 0, 3))

    # the request's numbers
    assert plate.body.bb.width == 90 mm and plate.body.bb.height == 70 mm, "plate 90 x 70"
    assert len(plate.screws) == 4, "four screws"
    assert plate.screws[0].c.center.x - plate.body.bb.left == 6 mm, "screws 6 in from the side"
    assert plate.screws[0].c.center.y - plate.body.bb.bottom == 6 mm, "screws 6 in from the bottom"
    assert plate.posts.round[1].center.x - plate.posts.round[0].center.x == 19 mm, "posts 19 apart"
    assert plate.posts.round[0].center.y - plate.body.bb.bottom == 28 mm, "posts 28 above the bottom"
    assert (plate.posts.round[0].center.x + plate.posts.round[1].center.x) / 2 == plate.body.bb.center_x,
        "posts on the centre line"
    assert plate.posts.flat[0].bb.top - plate.posts.round[0].bb.bottom == 7.2 mm, "7.2 across the flat"
    assert plate.posts.round[0].diameter == 8.2 mm, "8.2 mm post holes"
    assert distance(plate.marks.plus, plate.posts) >= 1.5 mm, "+ clear of its post"
    assert distance(plate.marks.minus, plate.posts) >= 1.5 mm, "- clear of its post"
    assert distance(plate.marks.spec, plate.marks.plus) >= 1.5 mm, "spec clear of the + mark"
    assert distance(plate.marks.name, plate.marks.spec) >= 1.5 mm, "name clear of the spec"
    assert plate.body.bb.top - plate.marks.name.bb.top >= 3 mm, "name inside the top edge"
    assert gasket.window.w.bb.width == 60 mm and gasket.window.w.bb.height == 36 mm, "window 60 x 36"
    assert gasket.window.w.bb.left - gasket.screws[0].c.bb.right >= 2 mm, "window clear of the screws"
}
