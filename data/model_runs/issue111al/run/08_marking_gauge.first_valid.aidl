# Request (workshop): a pencil marking gauge, 6 mm plywood, 3 parts. A fence 80 x 50 mm
# (R8 corners) with a 12.3 x 6.3 mm mortise for the beam, its centre 5 mm below the fence's
# middle, and an M4 pinch screw coming down from the middle of the top edge (T-slot, the nut
# 8 mm below the edge) whose slot runs 0.5 mm into the mortise so the screw's tip presses
# the beam; "MARKING GAUGE" engraved under the mortise (4 mm). A beam 150 x 12 mm with a
# V notch in its left end (8 mm wide at the end, 6 mm deep) for the pencil, a 4 mm hanging
# hole 7 mm from the right end, and a scale engraved from the notch's apex: a tick every
# millimetre from 5 to 130 mm (2 mm long, every 5 mm 3.5 mm, every 10 mm 5 mm), cm figures
# 1-13 (3.5 mm) above the long ticks. A thumb knob 26 mm across with ten 6 mm scallops round
# its rim and an M4 nut trap in the middle, to make the screw a thumb screw.

import "std/fasteners.aidl"

thickness 6 mm

fence_w = 80 mm
fence_h = 50 mm
mort_w = 12.3 mm
mort_h = 6.3 mm
mort_y = -5 mm
beam_l = 150 mm
beam_w = 12 mm
apex = 6 mm            # the notch's apex from the beam's left end: the scale's zero

assembly gauge {
    solid fence {
        body = RoundedRectangle(center=(0, 0), width=fence_w, height=fence_h, corner_radius=8 mm)
        hole mortise { r = Rectangle(center=(0, mort_y), width=mort_w, height=mort_h) }
        pinch = t_slot(size=4, length=fence_h / 2 - (mort_y + mort_h / 2) + 0.5 mm,
                       nut_depth=8 mm, cx=0, cy=fence_h / 2)
        AllowOverlap(pinch, mortise)
        drawing label {
            t = Text("MARKING GAUGE", position=(0, -18 mm), size=4)
        }
        assert body.width == 80 mm and body.height == 50 mm, "fence 80 x 50"
        assert mortise.r.width == 12.3 mm and mortise.r.height == 6.3 mm, "12.3 x 6.3 mortise"
        assert mortise.r.top.midpoint.y - pinch.slot.bb.bottom == 0.5 mm, "screw slot 0.5 mm into the mortise"
        assert body.bb.top - pinch.nut.center.y == 8 mm, "nut 8 mm below the edge"
        assert label.bb.top < mortise.r.bb.bottom, "label under the mortise"
    }

    solid beam {
        bar = Rectangle(bottom_left=(0, 0), width=beam_l, height=beam_w)
        hole notch {
            v = Polygon([(-1 mm, beam_w / 2 - 4 mm * 7 / 6), (apex, beam_w / 2),
                         (-1 mm, beam_w / 2 + 4 mm * 7 / 6)], overrun=true)
        }
        hole hang { c = Circle(center=(beam_l - 7 mm, beam_w / 2), diameter=4 mm) }
        drawing scale {
            for k in range(5, 131) {
                tick = Line((apex + k * 1 mm, 0.5 mm),
                            (apex + k * 1 mm,
                             0.5 mm + (5 mm if k % 10 == 0 else (3.5 mm if k % 5 == 0 else 2 mm))))
            }
            for c in range(1, 14) {
                fig = Text(str(c), position=(apex + c * 10 mm, 7 mm), size=3.5)
            }
        }
        assert bar.width == 150 mm and bar.height == 12 mm, "beam 150 x 12"
        assert beam_w == mort_w - 0.3 mm, "beam slides in the mortise"
        assert len(scale.tick) == 126, "ticks from 5 to 130 mm"
        assert len(scale.fig) == 13, "figures 1-13"
        assert scale.tick[125].start.x - apex == 130 mm, "last tick at 130 mm"
        assert scale.fig[12].bb.right < hang.c.center.x - 2 mm, "13 clear of the hanging hole"
        assert scale.fig[0].bb.top < bar.bb.top - 0.5 mm, "figures inside the beam"
        assert bar.bb.right - hang.c.center.x == 7 mm, "hanging hole 7 mm from the end"
    }

    solid knob {
        disc = Circle(center=(0, 0), diameter=26 mm)
        hole scallop { c = Circle(center=(13 mm, 0), diameter=6 mm) }
        grip = CircularPattern(scallop, 10, disc.center)
        nut = nut_trap(size=4, cx=0, cy=0)
        assert len(grip) == 10, "ten scallops"
    }

    Below(beam, fence, gap=10)
    AlignLeft(beam, fence)
    RightOf(knob, fence, gap=10)
    AlignTop(knob, fence)
}
