# Request (gifts): a personalised plate belt buckle for a 38 mm leather belt (4 mm thick),
# three layers glued: all 72 x 52 mm with 10 mm corner radii.
# - face, 3 mm walnut: the monogram "JR" in bold serif 22 mm tall, engraved filled and
#   centred, inside an engraved border line 4 mm in from the edge (6 mm corners);
# - spacer, 4 mm ply: a notch 42 mm tall, open to the left edge and 16 mm deep, so the
#   belt end can wrap round the back layer's bar, and an 11 mm pocket for the head of the
#   Chicago screw that is the hook;
# - back, 3 mm walnut: a window 8 x 42 mm whose outer side leaves an 8 mm bar at the left
#   edge, and a 4.2 mm hole for the Chicago screw's post 24 mm right of the centre.

units mm

W = 72 mm
H = 52 mm
R = 10 mm
BELT = 38 mm
STUD_X = 24 mm

assembly belt_buckle {
    solid face {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
        drawing art {
            border = RoundedRectangle(center=(0, 0), width=W - 8, height=H - 8,
                                      corner_radius=6)
            mono = Text("JR", (0, 0), size=22, font="serif:Bold", valign="middle",
                        fill=true)
        }
    }
    solid spacer {
        thickness 4 mm
        plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
        hole belt_room {
            notch = Rectangle(corner=(-W / 2 - 1, -21), opposite=(-W / 2 + 16, 21))
        }
        hole head_pocket { c = Circle(center=(STUD_X, 0), diameter=11) }
        # FIX after the first valid program: where the notch meets the rounded corners the
        # arms ended in knife-edge points; round those tips off
        Fillet([belt_room.notch, plate], 1.5)
    }
    solid back {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
        hole window {
            w = Rectangle(corner=(-W / 2 + 8, -21), opposite=(-W / 2 + 16, 21))
        }
        hole post { c = Circle(center=(STUD_X, 0), diameter=4.2) }
    }

    face.bb.center == (-85, 0)
    spacer.bb.center == (0, 0)
    back.bb.center == (85, 0)

    # glued: back at the bottom, spacer on it, face on top
    Place(back, position=(0, 0, 0))
    Place(spacer, on=back, position=(0, 0))
    Place(face, on=spacer, position=(0, 0))

    assert face.plate.width == 72 mm and face.plate.height == 52 mm, "72 x 52"
    assert face.art.mono.bb.height >= 20 mm, "monogram about 22 tall"
    assert face.plate.bb.right - face.art.border.bb.right == 4 mm, "border 4 in"
    # the serif J hangs below the baseline: 3 mm clear of the border is enough
    assert distance(face.art.mono, face.art.border) >= 3 mm, "monogram inside the border"
    assert back.window.w.bb.height - BELT >= 2 mm, "38 mm belt through the window"
    assert back.window.w.bb.left - back.plate.bb.left == 8 mm, "8 mm bar"
    assert back.window.w.bb.width == 8 mm, "window 8 wide"
    assert spacer.belt_room.notch.bb.height == 42 mm, "notch 42 tall"
    # (from the plate's drawn edge, which the face and back share: W0405 after the fix)
    assert spacer.belt_room.notch.bb.right - (spacer.plate.center.x - spacer.plate.width / 2) ==
        16 mm, "notch 16 deep"
    # the notch reaches past the window so the belt can turn into it
    assert spacer.belt_room.notch.bb.right >= back.window.w.bb.right, "notch over the window"
    assert back.post.c.center.x - back.plate.center.x == 24 mm, "post 24 right"
    assert spacer.head_pocket.c.center.x == back.post.c.center.x, "pocket over the post"
}
