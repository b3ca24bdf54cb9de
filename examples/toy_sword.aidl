# A toy sword, point up: a blade with a pointed tip and an engraved fuller,
# a crossguard with round knobs, a wrapped grip and a round pommel with a
# lanyard hole. The parts are stacked with Above/AlignCenterX constraints.
# Try: --set blade_length=400  --set guard_width=140  --set grip_length=110

param blade_length = 300 mm
param blade_width = 36 mm
param guard_width = 110 mm
param grip_length = 90 mm
param pommel_d = 34 mm

guard_h = 14 mm
grip_w = 24 mm
wraps = 7  # number of cord wraps drawn on the grip

solid sword {
    solid blade {
        edge = Polygon([(-blade_width / 2, 0), (blade_width / 2, 0),
                        (blade_width / 2, blade_length - blade_width),
                        (0, blade_length),
                        (-blade_width / 2, blade_length - blade_width)])
        # an engraved fuller runs up the middle of the blade
        drawing fuller {
            groove = Line((0, 20), (0, blade_length - blade_width - 15))
        }
        AlignCenterX(fuller, edge)
        fuller.bb.bottom == edge.bb.bottom + 20
    }

    solid guard {
        bar = RoundedRectangle(center=(0, -guard_h / 2), width=guard_width, height=guard_h,
                               corner_radius=4)
        # a round knob on each end of the crossguard
        for s in [-1, 1] {
            knob = Circle(center=(s * guard_width / 2, -guard_h / 2), radius=0.6 * guard_h)
        }
        Coincident(knob[0].center, bar.left.midpoint)
        Coincident(knob[1].center, bar.right.midpoint)
    }

    solid grip {
        handle = Rectangle(center=(0, -guard_h - grip_length / 2), width=grip_w, height=grip_length)
        # diagonal cord wraps, one per step down the grip
        drawing wrap {
            step = grip_length / wraps
            for i in range(wraps) {
                band = Line((-grip_w / 2, -guard_h - i * step),
                            (grip_w / 2, -guard_h - (i + 1) * step))
            }
        }
        CenterInside(wrap, handle)
    }

    solid pommel {
        knob = Circle(center=(0, -guard_h - grip_length - pommel_d / 2 + 6), diameter=pommel_d)
        hole lanyard {
            eye = Circle(center=(0, -guard_h - grip_length - pommel_d / 2 + 6), diameter=8)
        }
        Concentric(lanyard.eye, knob)
    }

    # blade on the guard, guard on the grip, pommel overlapping the grip's end
    Above(blade, guard.bar)
    Above(guard.bar, grip)
    Below(pommel, grip, gap=-6)
    AlignCenterX(blade, guard)
    AlignCenterX(grip, guard)
    AlignCenterX(pommel, grip)
}
