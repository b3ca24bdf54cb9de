# Request (workshop): "Laser-cut jaws for a wooden handscrew clamp. Each jaw is a stack of three
# layers: two 6 mm birch-ply outer layers and a 9 mm middle layer. A jaw is 250 mm long and
# 45 mm tall; its top edge tapers over the front 70 mm down to 30 mm at the nose so it reaches
# into corners; round the rear top corner R8. Two M10 threaded spindles pass through both jaws,
# on the jaw's centre line (22.5 mm up): the front one 80 mm from the nose, the rear one 180 mm
# from the nose. Outer layers: M10 clearance holes. The middle layer of jaw A holds an M10 nut in
# a hex trap at the FRONT spindle (clearance at the rear); jaw B's middle layer the other way
# round. Two round handles 50 mm across with 8 finger scallops (R5) round the rim, each with an
# M10 nut trap in the middle (two discs glued per handle, so cut four). Engrave 'A' or 'B' on
# each middle layer near the rear end, and 'HANDSCREW 250' on the outer layer."

units mm
thickness 6 mm
kerf 0.15 mm

import "std/fasteners.aidl"

jaw_len = 250 mm
jaw_h = 45 mm
nose_h = 30 mm
taper = 70 mm
front_x = 80 mm
rear_x = 180 mm

# one layer of a jaw; trap: 0 no nut trap, 1 at the front spindle, 2 at the rear spindle
def jaw_layer(trap=0, label="") -> solid {
    profile = Polygon([(0, 0), (jaw_len, 0), (jaw_len, jaw_h), (taper, jaw_h), (0, nose_h)])
    Fillet(profile.points[2], 8)
    if trap == 1 {
        front = nut_trap(size=10, cx=front_x, cy=jaw_h / 2)
    } else {
        front = clearance_hole(size=10, cx=front_x, cy=jaw_h / 2)
    }
    if trap == 2 {
        rear = nut_trap(size=10, cx=rear_x, cy=jaw_h / 2)
    } else {
        rear = clearance_hole(size=10, cx=rear_x, cy=jaw_h / 2)
    }
    drawing mark {
        t = Text(label, position=(215, jaw_h / 2), size=8, valign="middle")
    }
    assert profile.bb.width == 250 mm, "jaw 250 long"
    assert profile.bb.height == 45 mm, "jaw 45 tall"
    assert front.bb.center_x - profile.bb.left == 80 mm, "front spindle 80 from the nose"
    assert rear.bb.center_x - profile.bb.left == 180 mm, "rear spindle 180 from the nose"
    assert front.bb.center_y - profile.bb.bottom == 22.5 mm, "spindles on the centre line"
    assert distance(mark, rear) >= 3 mm, "label clear of the rear spindle"
}

def handle() -> solid {
    disc = Circle(center=(0, 0), diameter=50)
    hole scallop { c = Circle(center=(25, 0), radius=5) }
    CircularPattern(scallop, 8, disc.center)
    nut = nut_trap(size=10)
    Concentric(nut.hex, disc)
    assert disc.diameter == 50 mm, "handle 50 across"
}

assembly handscrew {
    outer = jaw_layer(trap=0, label="HANDSCREW 250")
    solid middle_a {
        thickness 9 mm
        layer = jaw_layer(trap=1, label="A")
    }
    solid middle_b {
        thickness 9 mm
        layer = jaw_layer(trap=2, label="B")
    }
    knob = handle()

    Below(middle_a, outer, gap=6)
    AlignLeft(middle_a, outer)
    Below(middle_b, middle_a, gap=6)
    AlignLeft(middle_b, middle_a)
    RightOf(knob, outer, gap=10)
    AlignTop(knob, outer)
}
