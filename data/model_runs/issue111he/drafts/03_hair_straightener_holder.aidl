# Request (bathroom): a wall holster for hair straighteners beside the mirror, 4 mm plywood.
# A back plate 110 mm wide and 260 mm tall with a fully rounded top, screwed to the wall by
# two 4 mm countersunk screws (holes 4.5 mm, heads 9 mm) on its centre line 200 mm apart.
# A pocket, open at top and bottom so the hot plates hang free and cool, 34 mm wide and
# 26 mm deep inside and 80 mm tall: the closed plates (about 30 x 20 mm) drop through, the
# wider handle rests on its rim. Its front is finger-jointed to its two sides (10 mm fingers)
# and the sides are glued into the back with two 20 mm tabs each. "HOT" engraved in filled
# bold letters on the pocket's front. At the bottom, two hooks curving up out of the plate's
# sides to wind the cord round, leaving a 12 mm throat.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
inner_w = 34 mm
inner_d = 26 mm
pocket_h = 80 mm

def side_panel() -> solid {
    # lies with the back edge (tab tips) at x = -17 - 2 and the front edge at x = +19 - 2
    body = Rectangle(center=(0, 0), width=inner_d + 2 * t, height=pocket_h)
    back_tabs = tab_and_slot(part="tab", length=pocket_h, thickness=t, tabs=2, tab=20 mm,
                             screw=0, rotation=90 deg, cx=-(inner_d + 2 * t) / 2, cy=0 mm)
    front_joint = finger_edge(length=pocket_h, thickness=t, finger=10 mm, start="gap",
                              rotation=-90 deg, cx=(inner_d + 2 * t) / 2, cy=0 mm)
}

assembly straightener_holder {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=110, height=260,
                                corner_radii=[55, 55, 8, 8])
        axis = Line((0, -140), (0, 140), construction=true)
        horn = Stroke(Arc(start=(-45, -118), through=(-66, -112), end=(-72, -92)), width=10)
        other_horn = Mirrored(horn, axis)
        # FIX after the first valid program: the hooks met the plate in sharp inside corners
        # (a notch at the bottom corner, a weak root): round where they cross the plate
        # (a Stroke's crossings are not found: the points, worked out by hand)
        Fillet([(-55, -112.92), (-54.91, -123.19), (55, -112.92), (54.91, -123.19)], 4)
        hole screws {
            upper = Circle(center=(0, 95), diameter=4.5)
            lower = Circle(center=(0, -105), diameter=4.5)
        }
        Countersink(screws, diameter=9)
        left_mortise = tab_and_slot(part="slot", length=pocket_h, thickness=t, tabs=2,
                                    tab=20 mm, screw=0, rotation=90 deg,
                                    cx=-(inner_w + t) / 2, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=pocket_h, thickness=t, tabs=2,
                                     tab=20 mm, screw=0, rotation=90 deg,
                                     cx=(inner_w + t) / 2, cy=0 mm)
        assert screws.upper.center.y - screws.lower.center.y == 200 mm, "screws 200 apart"
        assert body.width == 110 mm and body.height == 260 mm, "plate 110 x 260"
        assert distance(screws, left_mortise) >= 10 mm, "screws clear of the pocket"
    }

    solid front {
        body = Rectangle(center=(0, 0), width=inner_w + 2 * t, height=pocket_h)
        left_joint = finger_edge(length=pocket_h, thickness=t, finger=10 mm, start="tab",
                                 rotation=90 deg, cx=-(inner_w + 2 * t) / 2, cy=0 mm)
        right_joint = finger_edge(length=pocket_h, thickness=t, finger=10 mm, start="tab",
                                  rotation=-90 deg, cx=(inner_w + 2 * t) / 2, cy=0 mm)
        drawing word {
            hot = Text("HOT", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                       fill=true)
        }
        assert body.width - 2 * t == 34 mm, "34 mm inside"
        assert body.height == 80 mm, "80 mm tall"
        assert distance(word, left_joint) >= 2 mm and distance(word, right_joint) >= 2 mm,
            "word clear of the fingers"
    }

    left_side = side_panel()
    right_side = side_panel()
    assert left_side.body.width - 2 * t == 26 mm, "26 mm deep inside"

    RightOf(front, back, gap=10)
    AlignTop(front, back)
    Below(left_side, front, gap=10)
    AlignLeft(left_side, front)
    Below(right_side, left_side, gap=10)
    AlignLeft(right_side, left_side)
}
