# Request (music): a 400 mm rainstick as a square tube, 50 x 50 mm outside, from 3 mm ply,
# finger-jointed on all edges (both end caps glued in after filling it with rice). 4 mm
# dowel pins are pushed through 4.2 mm holes to make the maze the grains rattle through:
# - 16 pins from front to back, at x = +-(6 + 24 k) mm from the middle (k = 0..7), their
#   heights stepping -14, -7, 0, 7, 14, 7, 0, -7 mm from the tube's axis (mirrored about the
#   middle, so the front and back holes line up whichever way the back is turned);
# - 28 pins from the lid to the bottom, at x = +-(18 + 24 k) mm (k = 0..6), two at each,
#   +-7 mm across the tube for even k and +-14 mm for odd k.
# Each end cap has a filled raindrop engraved on it, 30 mm tall, pointing up.

units mm
thickness 3 mm
import "std/joints.aidl"

T = 3 mm
LEN = 400 mm
SIDE = 50 mm
PIN = 4.2 mm
H_STEPS = [-14, -7, 0, 7, 14, 7, 0, -7]

# front-to-back pins, about the panel's middle
def across_pins() -> hole {
    ref = Point(0, 0, construction=true)
    for k in range(8) {
        r = Circle(center=(6 + 24 * k, H_STEPS[k]), diameter=PIN)
        l = Circle(center=(-6 - 24 * k, H_STEPS[k]), diameter=PIN)
    }
    Rigid(self)
}

# lid-to-bottom pins, symmetric both ways
def down_pins() -> hole {
    ref = Point(0, 0, construction=true)
    for k in range(7) {
        a = Circle(center=(18 + 24 * k, 7 if k % 2 == 0 else 14), diameter=PIN)
        b = Circle(center=(18 + 24 * k, -7 if k % 2 == 0 else -14), diameter=PIN)
        c = Circle(center=(-18 - 24 * k, 7 if k % 2 == 0 else 14), diameter=PIN)
        d = Circle(center=(-18 - 24 * k, -7 if k % 2 == 0 else -14), diameter=PIN)
    }
    Rigid(self)
}

# a raindrop, tip toward +x (dir = 1) or -x (dir = -1): the end caps lie on their side
def drop(dir=1) -> drawing {
    ref = Point(0, 0, construction=true)
    d = Hull(Circle(center=(-5 * dir, 0), radius=10), Point(15 * dir, 0), fill=true)
    Rigid(self)
}

assembly rainstick {
    box = finger_box(length=LEN, depth=SIDE, height=SIDE, thickness=T, finger=10 mm)

    front_pins = across_pins()
    back_pins = across_pins()
    lid_pins = down_pins()
    bottom_pins = down_pins()
    Coincident(front_pins.ref, box.front.outline.center)
    Coincident(back_pins.ref, box.back.outline.center)
    Coincident(lid_pins.ref, box.lid.outline.center)
    Coincident(bottom_pins.ref, box.bottom.outline.center)
    CutInto(front_pins, box.front)
    CutInto(back_pins, box.back)
    CutInto(lid_pins, box.lid)
    CutInto(bottom_pins, box.bottom)

    # the left cap's top edge is at -x, the right's at +x: each drop points there
    left_drop = drop(dir=-1)
    right_drop = drop(dir=1)
    Coincident(left_drop.ref, box.left.outline.center)
    Coincident(right_drop.ref, box.right.outline.center)
    CutInto(left_drop, box.left)
    CutInto(right_drop, box.right)

    # the request's numbers
    assert box.front.outline.width == 400 mm, "400 mm long"
    assert box.left.outline.width == 50 mm and box.left.outline.height == 50 mm, "50 x 50 tube"
    assert len(front_pins.r) + len(front_pins.l) == 16, "16 pins across"
    assert 4 * len(lid_pins.a) == 28, "28 pins down"
    assert front_pins.r[0].diameter == 4.2 mm, "4.2 mm holes"
    assert front_pins.r[1].center.x - front_pins.r[0].center.x == 24 mm, "24 mm pitch"
    assert left_drop.d.bb.width == 30 mm, "drop 30 mm tall"
    assert distance(front_pins, box.front.core) >= 0 mm, "pins inside the joints"
}
