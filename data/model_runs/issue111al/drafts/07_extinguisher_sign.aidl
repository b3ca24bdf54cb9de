# Request (signs): a projecting "flag" sign that marks a fire extinguisher down a corridor,
# 3 mm red acrylic, 2 parts glued. The flag: 160 x 120 mm, standing out from the wall, its
# two outer corners R10, its wall edge on two 20 mm tabs (glued) into a wall plate 40 x 170 mm
# (R5 corners) that takes two M4 countersunk screws 72 mm above and below its middle
# (8.5 mm heads). On the flag: an extinguisher silhouette cut through (a body 24 x 50 mm
# with a round top, valve, lever and a hose), "FIRE" (18 mm bold) and "EXTINGUISHER" (8 mm
# bold, at most 80 mm wide) engraved filled to its right, and a down arrow cut through under
# the words (pointing to the extinguisher below the sign). Everything at least 8 mm from the
# flag's edges.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

T = 3 mm
flag_w = 160 mm     # from the wall face out
flag_h = 120 mm

assembly sign {
    solid flag {
        # drawn with the wall edge (the tabs' tips) on x = 0; the face starts at x = T
        panel = RoundedRectangle(bottom_left=(0, 0), width=flag_w + T, height=flag_h,
                                 corner_radii=[0, 10 mm, 10 mm, 0])
        tabs = tab_and_slot(part="tab", length=flag_h, thickness=T, tabs=2, tab=20 mm,
                            screw=0, rotation=90 deg, cx=0, cy=flag_h / 2)
        hole icon {
            body = RoundedRectangle(center=(45 mm, 50 mm), width=24 mm, height=50 mm,
                                    corner_radii=[12 mm, 12 mm, 3 mm, 3 mm])
            valve = Rectangle(center=(45 mm, 78 mm), width=8 mm, height=10 mm)
            lever = Rectangle(start=(40 mm, 82 mm), end=(60 mm, 88 mm), width=3 mm)
            hose = Stroke(Arc(start=(49 mm, 80 mm), through=(64 mm, 72 mm), end=(63 mm, 45 mm)),
                          3 mm)
        }
        hole arrow {
            a = Polygon([(115, 12), (125, 26), (119, 26), (119, 40), (111, 40), (111, 26),
                         (105, 26)])
        }
        drawing words {
            fire = Text("FIRE", position=(115 mm, 80 mm), size=18, font="sans:Bold", fill=true)
            ext = Text("EXTINGUISHER", position=(115 mm, 58 mm), size=8, font="sans:Bold",
                       max_width=80 mm, fill=true)
        }
        assert panel.width - T == 160 mm and panel.height == 120 mm, "flag 160 x 120"
        assert icon.body.width == 24 mm and icon.body.height == 50 mm, "body 24 x 50"
        assert words.ext.bb.width <= 80 mm, "EXTINGUISHER at most 80 mm wide"
        assert words.ext.bb.right <= panel.bb.right - 8 mm, "words 8 mm from the edge"
        assert words.fire.bb.top <= panel.bb.top - 8 mm, "FIRE 8 mm from the top"
        assert icon.bb.left >= T + 8 mm and icon.bb.top <= flag_h - 8 mm, "icon 8 mm in"
        assert arrow.bb.bottom >= 8 mm, "arrow 8 mm from the bottom"
        assert arrow.bb.top < words.ext.bb.bottom, "arrow under the words"
        assert words.ext.bb.left > icon.bb.right, "words right of the icon"
    }

    solid plate {
        body = RoundedRectangle(center=(0, 0), width=40 mm, height=170 mm, corner_radius=5 mm)
        slots = tab_and_slot(part="slot", length=flag_h, thickness=T, tabs=2, tab=20 mm,
                             screw=0, rotation=90 deg, cx=0, cy=0)
        top_screw = clearance_hole(size=4, cx=0, cy=72 mm)
        low_screw = clearance_hole(size=4, cx=0, cy=-72 mm)
        Countersink([top_screw, low_screw], diameter=8.5 mm)
        assert body.width == 40 mm and body.height == 170 mm, "plate 40 x 170"
        assert top_screw.c.center.y - low_screw.c.center.y == 144 mm, "screws 72 mm up and down"
    }

    RightOf(plate, flag, gap=10)
    AlignCenterY(plate, flag)
}
