# Request: a solder-paste printing jig for my 70 x 50 mm PCBs (1.6 mm thick). Three plates,
# each 160 x 120 mm with 4 mm corner radii:
# - base, 3 mm acrylic: four M3 clearance holes 6 mm in from each corner (it is screwed to the
#   nest) and two 4 mm holes for register pins on the centre line, 70 mm either side of centre;
# - nest, 1.5 mm acrylic: the same screw and pin holes, and the board's pocket in the middle,
#   70.2 x 50.2 mm (0.1 mm play each side), with 3 mm relief holes at its four corners and a
#   20 mm finger notch centred on each short (50 mm) side of the pocket; "PCB 70 x 50 x 1.6"
#   engraved 5 mm tall under the pocket;
# - stencil frame, 3 mm acrylic, lifts off over the pins: a 90 x 70 mm window (2 mm corner
#   radii) centred over the pocket, 4.2 mm pin holes at the same places, no screw holes, and
#   "PASTE JIG 70 x 50" engraved 5 mm tall above the window.
# Stacked: base, nest on it, frame on the nest.

import "std/plates.aidl"

pcb_w = 70 mm
pcb_h = 50 mm
play = 0.1 mm
plate_w = 160 mm
plate_h = 120 mm
pin_off = 70 mm
pw = pcb_w / 2 + play
ph = pcb_h / 2 + play

assembly jig {
    solid base {
        thickness 3 mm
        p = mounting_plate(width=plate_w, height=plate_h, corner_radius=4 mm, screw=3, inset=6 mm)
        hole pins {
            l = Circle(center=(-pin_off, 0), diameter=4 mm)
            r = Circle(center=(pin_off, 0), diameter=4 mm)
        }
    }

    solid nest {
        thickness 1.5 mm
        p = mounting_plate(width=plate_w, height=plate_h, corner_radius=4 mm, screw=3, inset=6 mm)
        hole pins {
            l = Circle(center=(-pin_off, 0), diameter=4 mm)
            r = Circle(center=(pin_off, 0), diameter=4 mm)
        }
        hole pocket {
            board = Rectangle(center=(0, 0), width=2 * pw, height=2 * ph)
            tl = Circle(center=(-pw, ph), diameter=3 mm)
            tr = Circle(center=(pw, ph), diameter=3 mm)
            bl = Circle(center=(-pw, -ph), diameter=3 mm)
            br = Circle(center=(pw, -ph), diameter=3 mm)
            notch_l = Circle(center=(-pw, 0), diameter=20 mm)
            notch_r = Circle(center=(pw, 0), diameter=20 mm)
        }
        drawing label {
            t = Text("PCB 70 x 50 x 1.6", position=(0, -42), size=5, valign="middle")
        }
    }

    solid frame {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=4 mm)
        hole window {
            w = RoundedRectangle(center=(0, 0), width=90 mm, height=70 mm, corner_radius=2 mm)
        }
        hole pins {
            l = Circle(center=(-pin_off, 0), diameter=4.2 mm)
            r = Circle(center=(pin_off, 0), diameter=4.2 mm)
        }
        drawing label {
            t = Text("PASTE JIG 70 x 50", position=(0, 47), size=5, valign="middle")
        }
    }

    # on the sheet: side by side
    RightOf(nest, base, gap=6)
    AlignTop(nest, base)
    RightOf(frame, nest, gap=6)
    AlignTop(frame, nest)

    # stacked
    Place(base, position=(0, 0, 0), face="up")
    Place(nest, position=(0, 0, 3), face="up")
    Place(frame, position=(0, 0, 4.5), face="up")

    assert base.p.body.width == 160 mm and base.p.body.height == 120 mm, "160 x 120 plates"
    assert frame.body.width == 160 mm and frame.body.height == 120 mm, "160 x 120 frame"
    assert len(base.p.corner) == 4 and len(nest.p.corner) == 4, "four M3 screws"
    assert base.p.corner[0].c.center.x - base.p.body.bb.left == 6 mm, "screws 6 mm in"
    assert base.p.corner[0].c.center.y - base.p.body.bb.bottom == 6 mm, "screws 6 mm in"
    assert distance(base.pins.l.center, base.pins.r.center) == 140 mm, "pins 70 either side"
    assert base.pins.l.diameter == 4 mm and frame.pins.l.diameter == 4.2 mm, "pin holes"
    assert nest.pocket.board.width == 70.2 mm and nest.pocket.board.height == 50.2 mm, "pocket"
    assert nest.pocket.tl.diameter == 3 mm, "3 mm corner reliefs"
    assert nest.pocket.notch_l.diameter == 20 mm, "20 mm finger notches"
    assert nest.pocket.notch_l.center.x - nest.pocket.board.bb.left == 0 mm, "notch on the short side"
    assert nest.pocket.notch_l.center.y - nest.pocket.board.center.y == 0 mm, "notch centred"
    assert frame.window.w.width == 90 mm and frame.window.w.height == 70 mm, "90 x 70 window"
    assert distance(frame.window.w.center, frame.body.center) == 0 mm, "window centred"
    assert distance(nest.pocket.board.center, nest.p.body.center) == 0 mm, "pocket centred"
    assert nest.label.t.size == 5 mm and frame.label.t.size == 5 mm, "5 mm labels"
    assert nest.label.t.bb.top < nest.pocket.board.bb.bottom, "label under the pocket"
    assert frame.label.t.bb.bottom > frame.window.w.bb.top, "label above the window"
}
