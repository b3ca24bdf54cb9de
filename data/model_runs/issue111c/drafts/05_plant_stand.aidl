# Plant stand: two identical 6 mm plywood panels that cross-halve into an X
# (seen from above). Each panel is a trapezoid 250 mm tall, 220 mm wide at the
# floor and 160 mm at the top, with a 120 mm wide, 40 mm high round-topped arch
# cut out between the feet. Panel A is slotted 125 mm down from the middle of
# its top, panel B 125 mm up from the middle of its bottom (the arch's top):
# 6 mm + 0.2 mm clearance slots. The pot sits on the 160 mm tops.
import "std/joints.aidl"

thickness 6 mm

param h = 250 mm, min = 150 mm, max = 400 mm

def panel_shape() -> solid {
    body = Trapezoid(center=(0, 0), bottom_width=220, top_width=160, height=h)
    hole arch {
        box = Rectangle(center=(0, -h / 2 + 20), width=120, height=40)
    }
    AlignBottom(arch, body)
    AlignCenterX(arch, body)
}

assembly stand {
    solid a {
        p = panel_shape()
        s = cross_halving(depth=125 mm, thickness=6 mm, clearance=0.2 mm, cx=0 mm, cy=h / 2)
    }
    solid b {
        p = panel_shape()
        s = cross_halving(depth=125 mm, thickness=6 mm, clearance=0.2 mm, rotation=180 deg,
                          cx=0 mm, cy=-h / 2)
    }
    RightOf(b, a, gap=10)
    AlignBottom(b, a)
}

assert stand.a.p.body.bb.height == 250 mm, "250 mm tall"
assert stand.a.p.body.bottom_width == 220 mm and stand.a.p.body.top_width == 160 mm, "220 / 160 mm"
assert stand.a.s.cut.bb.height == 125 mm, "A slotted 125 mm from the top"
assert stand.b.s.cut.bb.height == 125 mm, "B slotted 125 mm from the bottom"
assert stand.a.s.cut.bb.width == 6.2 mm, "6 mm + 0.2 mm"
assert stand.a.s.cut.bb.height + stand.b.s.cut.bb.height == 250 mm, "the depths add to the height"
