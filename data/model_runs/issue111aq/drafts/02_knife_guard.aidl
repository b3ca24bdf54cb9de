# Request (kitchen): a blade guard for a 200 mm chef's knife, three layers of 3 mm ply
# glued together: a front face, a spacer and a back face. The blade is 205 mm from heel to
# tip and 48 mm tall at the heel; its spine runs straight for 120 mm, then drops 10 mm to
# the tip; the edge sweeps up to the tip through (180, -26) and (120, -44) (heel's spine
# corner at (0, 0), spine up). The guard's outline is the blade grown by 12 mm, cut off
# square at the heel (x = 0). The spacer is that outline with the blade's pocket (1 mm
# clearance all round) cut out and open at the heel. Three 4 mm holes through all three
# layers for brass pins: two 20 mm in from the heel, centred in the spine wall and in the
# edge wall, and one 7 mm beyond the tip. The front face has "CHEF 200" engraved in filled
# bold letters 10 mm tall, centred on the blade.

thickness 3 mm

# FIX after the first valid program: corners=[0, 1, 2, 5] (was [0, 2, 5]): the spine is
# two straight runs, as requested; the smooth spline bulged the spine 1.6 mm above y = 0
# and the edge 0.8 mm below the heel (--describe: outline top 13.575, not 12).
BLADE = [(0, 0), (120, 0), (205, -10), (180, -26), (120, -44), (0, -48)]
wall = 12 mm
clear = 1 mm

def pins() -> hole {
    spine_pin = Circle(center=(20, clear + (wall - clear) / 2), diameter=4)
    edge_pin = Circle(center=(20, -48 - clear - (wall - clear) / 2), diameter=4)
    tip_pin = Circle(center=(205 + 7, -10), diameter=4)
}

def face(label=false) -> solid {
    blade = Spline(BLADE, closed=true, corners=[0, 1, 2, 5], construction=true)
    outline = Intersect(Offset(blade, wall), Rectangle(bottom_left=(0, -80), width=240, height=120))
    p = pins()
    if label {
        drawing name {
            t = Text("CHEF 200", position=(95, -22), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    assert blade.points[2].x - blade.points[0].x == 205 mm, "blade 205 mm heel to tip"
    assert blade.points[0].y - blade.points[5].y == 48 mm, "48 mm tall at the heel"
}

def spacer() -> solid {
    blade = Spline(BLADE, closed=true, corners=[0, 1, 2, 5], construction=true)
    outline = Intersect(Offset(blade, wall), Rectangle(bottom_left=(0, -80), width=240, height=120))
    hole pocket {
        b = Spline(BLADE, closed=true, corners=[0, 1, 2, 5], construction=true)
        cavity = Offset(b, clear)
        mouth = Rectangle(bottom_left=(-3, -48 - clear), width=6, height=48 + 2 * clear, overrun=true)
    }
    p = pins()
}

assembly knife_guard {
    front = face(label=true)
    middle = spacer()
    back = face(label=false)
    Below(middle, front, gap=8)
    Below(back, middle, gap=8)
    AlignLeft(middle, front)
    AlignLeft(back, front)
    assert front.p.spine_pin.diameter == 4 mm and front.p.tip_pin.diameter == 4 mm, "4 mm pin holes"
    assert front.p.spine_pin.center.x - front.bb.left == 20 mm, "pins 20 mm in from the heel"
    assert front.name.t.size == 10 mm, "letters 10 mm tall"
}
