# Office: a wall-mounted whiteboard-marker tray from 3 mm plywood, three glued parts.
# Back plate 220 x 70 mm with two 4.5 mm screw holes countersunk 9 mm, 20 mm in from
# each end and 15 mm down from the top, and "MARKERS" engraved (10 mm letters) in the
# middle above the shelf. Shelf 220 x 40 mm (tabs included): two 30 mm tabs on its rear
# edge, spread over 200 mm, glued into mortises in the back whose centre line is 8 mm
# above the back's bottom edge. Front lip 220 x 18 mm (tabs included): two 30 mm tabs
# into mortises in the shelf, their centre line 4 mm in from the shelf's front edge.
# Mortises 0.1 mm clearance.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 6 mm
param fit = 0.1 mm, min = 0 mm, max = 0.3 mm

assembly tray {
    solid back {
        body = Rectangle(center=(0, 0), width=220, height=70)
        mort = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=30 mm,
                            screw=0, clearance=fit, cx=0 mm, cy=-35 mm + 8 mm)
        hole screw {
            c = Circle(center=(-90, 20), diameter=4.5)
        }
        screws = LinearPattern(screw, 2, (180, 0))
        Countersink(screws, diameter=9)
        drawing label {
            word = Text("MARKERS", position=(0, 0), size=10, valign="middle")
        }
    }

    solid shelf {
        body = Rectangle(center=(0, 100), width=220, height=40)
        # FIX after the first valid program: rotation 0 cuts toward -y from (cx, cy), i.e. a
        # panel BELOW its edge; this panel lies above its rear edge (y = 80): rotation 180,
        # cy on the edge (the first program's cy = 80 + t gave 4 mm tabs). The template
        # cuts only over `length` (200), leaving 10 mm stubs at the ends that would hit
        # the back's face: they are cut back by `ends`.
        tabs = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=2, tab=30 mm,
                            screw=0, cx=0 mm, cy=80 mm, rotation=180 deg)
        hole ends {
            l = Rectangle(bottom_left=(-111, 79), width=12, height=1 + t)
            r = Rectangle(bottom_left=(99, 79), width=12, height=1 + t)
        }
        mort = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=30 mm,
                            screw=0, clearance=fit, cx=0 mm, cy=120 mm - 4 mm)
    }

    solid lip {
        body = Rectangle(center=(0, 170), width=220, height=18)
        tabs = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=2, tab=30 mm,
                            screw=0, cx=0 mm, cy=161 mm, rotation=180 deg)
        hole ends {
            l = Rectangle(bottom_left=(-111, 160), width=12, height=1 + t)
            r = Rectangle(bottom_left=(99, 160), width=12, height=1 + t)
        }
    }

    assert back.body.width == 220 mm and back.body.height == 70 mm, "back 220 x 70"
    assert shelf.body.width == 220 mm and shelf.body.height == 40 mm, "shelf 220 x 40"
    assert lip.body.width == 220 mm and lip.body.height == 18 mm, "lip 220 x 18"
    assert back.screw.c.center.x - back.body.bb.left == 20 mm, "screw 20 mm in from the end"
    assert back.body.bb.top - back.screw.c.center.y == 15 mm, "screws 15 mm below the top"
    assert back.mort.bb.center_y - back.body.bb.bottom == 8 mm, "mortises 8 mm above the bottom"
    assert shelf.body.bb.top - shelf.mort.bb.center_y == 4 mm, "lip mortises 4 mm from the front"
    assert len(back.screws) == 2, "two screws"
}
