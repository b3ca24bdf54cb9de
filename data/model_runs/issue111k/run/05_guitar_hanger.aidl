# Music-room guitar wall hanger, back plate, 6 mm plywood: 80 mm wide, 140 mm tall, the top a
# full half circle (radius 40 mm), the bottom corners rounded 8 mm. Two 4.5 mm screw holes on
# the centre line, 20 mm below the top and 20 mm above the bottom, countersunk 9 mm (90 deg).
# Two horizontal mortises 15 x 6.2 mm for the yoke's tabs, centred 20 mm either side of the
# centre line, 65 mm above the bottom edge. "MUSIC ROOM" engraved along the top arc, 5 mm
# letters, their baselines on a 30 mm radius about the half circle's centre, centred at the top.

import "std/plates.aidl"

thickness 6 mm

solid hanger {
    plate = RoundedRectangle(center=(0, 0), width=80, height=140, corner_radii=[40, 40, 8, 8])

    hole top_screw {
        c = Circle(center=(0, 50), diameter=4.5)
    }
    hole bottom_screw {
        c = Circle(center=(0, -50), diameter=4.5)
    }
    Countersink([top_screw, bottom_screw], diameter=9)

    hole mortises {
        left = Rectangle(center=(-20, -5), width=15, height=6.2)
        right = Rectangle(center=(20, -5), width=15, height=6.2)
    }

    label = text_on_arc(text="MUSIC ROOM", radius=30 mm, size=5 mm, angle=90 deg, cx=0 mm, cy=30 mm)

    assert plate.width == 80 mm and plate.height == 140 mm, "80 x 140 plate"
    assert plate.bb.top - top_screw.c.center.y == 20 mm, "top screw 20 mm below the top"
    assert bottom_screw.c.center.y - plate.bb.bottom == 20 mm, "bottom screw 20 mm above the bottom"
    assert top_screw.c.center.x == plate.center.x and bottom_screw.c.center.x == plate.center.x, "screws on the centre line"
    assert top_screw.c.diameter == 4.5 mm, "4.5 mm screws"
    assert mortises.left.width == 15 mm and mortises.left.height == 6.2 mm, "15 x 6.2 mortises"
    assert mortises.right.center.x - plate.center.x == 20 mm, "mortise 20 mm right"
    assert plate.center.x - mortises.left.center.x == 20 mm, "mortise 20 mm left"
    assert mortises.left.center.y - plate.bb.bottom == 65 mm, "mortises 65 mm up"
    assert plate.bb.top - 40 mm == 30 mm, "half circle's centre at y = 30"
    assert label.ch[0].size == 5 mm, "5 mm letters"
    assert len(label.ch) == 9, "MUSIC ROOM: 9 letters"
    assert label.bb.top < plate.bb.top, "text inside the top arc"
}
