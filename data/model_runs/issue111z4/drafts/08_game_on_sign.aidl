# Signs: a "GAME ON" wall sign for a games room, cut from 3 mm acrylic: the letters
# themselves, sans Bold, 50 mm tall (cap height), standing on a rail as wide as the word and
# 20 mm tall; the letters' baseline 3 mm below the rail's top so every letter is joined to it.
# Two keyholes in the rail (head 8 mm, shank slot 4 mm wide running 8 mm up from the head's
# centre), heads 25 mm in from the rail's ends and 7 mm above its bottom edge.

units mm
thickness 3 mm

import "std/plates.aidl"

solid sign {
    word = Text("GAME ON", position=(0, 17), size=50, font="sans:Bold")
    rail = Rectangle(center=(word.center.x, 10), width=word.bb.width, height=20)
    word.position.y == rail.bb.top - 3 mm
    # fix after the first check: AlignCenterX(rail, word) dropped (W0401: the rail's centre is
    # already word.center.x)

    left = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, direction=90 deg)
    right = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, direction=90 deg)
    HorizontalDistance(rail.bottom_left, left.head_hole.center, 25)
    HorizontalDistance(right.head_hole.center, rail.bottom_right, 25)
    VerticalDistance(rail.bottom_left, left.head_hole.center, 7)
    VerticalDistance(rail.bottom_right, right.head_hole.center, 7)

    assert word.size == 50 mm, "letters 50 mm tall"
    assert rail.bb.height == 20 mm, "rail 20 mm tall"
    assert rail.bb.width == word.bb.width, "rail as wide as the word"
    assert rail.bb.top - word.position.y == 3 mm, "baseline 3 mm below the rail's top"
    assert left.head_hole.center.x - rail.bb.left == 25 mm, "keyholes 25 mm in"
    assert rail.bb.right - right.head_hole.center.x == 25 mm, "keyholes 25 mm in"
    assert left.head_hole.diameter == 8 mm and left.slot.width == 4 mm, "keyhole 8 / 4"
}
