# Request: a fin-alignment jig for gluing the three fins of a model rocket on a BT-50 body
# tube (24.8 mm across), cut from 3 mm acrylic. Two 160 mm discs 100 mm apart (inside),
# each with a 25.3 mm hole for the tube (0.5 mm play) and three radial fin slots 3.2 mm wide
# (3 mm fins) at 0, 120 and 240 degrees, running out to 70 mm from the centre and opening
# into the tube hole so each fin's root touches the tube. The discs are held by three
# pillars, 30 mm wide (50 to 80 mm from the centre) between the fins at 60, 180 and 300
# degrees, each with one 20 mm tab into a mortise in each disc. The top disc is engraved
# "BT-50" (5 mm) over the tube hole along a 32 mm circle, and "FIN 1", "FIN 2", "FIN 3"
# (4 mm) along a 75 mm circle past the end of each slot.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
D = 160 mm
tube = 24.8 mm
play = 0.5 mm
fin_t = 3 mm
slot_w = 3.2 mm
slot_out = 70 mm
gap_h = 100 mm
p_in = 50 mm
p_out = 80 mm
fins = [0 deg, 120 deg, 240 deg]
posts = [60 deg, 180 deg, 300 deg]

def disc(marked=false) -> solid {
    body = Circle(center=(0, 0), diameter=D)
    Fixed(body)
    hole guide {
        bore = Circle(center=(0, 0), diameter=tube + play)
        for a in fins {
            s = Rectangle(start=(5 mm * cos(a), 5 mm * sin(a)),
                          end=(slot_out * cos(a), slot_out * sin(a)), width=slot_w)
        }
    }
    for a in posts {
        m = tab_and_slot(part="slot", length=p_out - p_in, thickness=t, tabs=1, tab=20 mm,
                         screw=0, rotation=a, cx=(p_in + p_out) / 2 * cos(a),
                         cy=(p_in + p_out) / 2 * sin(a))
    }
    if marked {
        drawing marks {
            inner = Circle(center=(0, 0), radius=32, construction=true)
            outer = Circle(center=(0, 0), radius=75, construction=true)
            name = Text("BT-50", along=inner, size=5, valign="middle")
            for i in range(3) {
                f = Text(f"FIN {i + 1}", along=outer, angle=fins[i], size=4, valign="middle")
            }
        }
    }
}

def pillar() -> solid {
    # x: the distance from the jig's axis; y: the height above the bottom disc's top face
    body = Rectangle(bottom_left=(p_in, -t), width=p_out - p_in, height=gap_h + 2 * t)
    low = tab_and_slot(part="tab", length=p_out - p_in, thickness=t, tabs=1, tab=20 mm,
                       screw=0, rotation=180 deg, cx=(p_in + p_out) / 2, cy=-t)
    high = tab_and_slot(part="tab", length=p_out - p_in, thickness=t, tabs=1, tab=20 mm,
                        screw=0, cx=(p_in + p_out) / 2, cy=gap_h + t)
}

assembly jig {
    bottom = disc()
    top = disc(marked=true)
    for i in range(3) {
        post = pillar()
        Place(post, position=(-t / 2 * sin(posts[i]), t / 2 * cos(posts[i]), 0),
              face=(sin(posts[i]), -cos(posts[i]), 0), up="up")
    }

    # flat: the discs side by side, the pillars beside them
    RightOf(top, bottom, gap=5)
    AlignCenterY(top, bottom)
    RightOf(post[0], top, gap=5)
    AlignBottom(post[0], top)
    for i in range(1, 3) {
        RightOf(post[i], post[i - 1], gap=5)
        AlignBottom(post[i], post[i - 1])
    }

    Place(bottom, position=(0, 0, -t), face="up")
    Place(top, position=(0, 0, gap_h), face="up")

    assert top.guide.bore.diameter - tube == 0.5 mm, "0.5 mm play round the tube"
    assert slot_w - fin_t == 0.2 mm
    assert len(top.guide.s) == 3 and len(post) == 3
    assert post[0].body.bb.height - 2 * t == 100 mm, "discs 100 mm apart inside"
    assert post[0].body.bb.width == 30 mm
}
