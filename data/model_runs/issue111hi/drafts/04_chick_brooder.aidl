# Request (pets): a brooder box for a batch of day-old chicks, in 6 mm ply. A
# closed finger-jointed box 500 mm long, 350 mm deep and 300 mm tall outside
# (25 mm fingers). The lid is vented by 45 holes of 8 mm (5 rows x 9 columns,
# 30 mm pitch, centred) and has a 40 mm hole for the heat plate's cord 50 mm
# from its left end. The front has a 200 x 120 mm viewing window whose centre
# is 30 mm above the panel's centre, covered from inside by a 3 mm clear
# acrylic pane 236 x 156 mm (6 mm corner radius) held by four M4 screws
# (4.5 mm holes) at 109 mm and 69 mm either side of the window's centre, the
# same holes in pane and front. "CHICKS" is engraved filled in bold sans,
# 30 mm letters, centred 95 mm below the front's centre.

import "std/joints.aidl"

t = 6 mm
thickness t

screw_at = [(-109, -69), (109, -69), (-109, 69), (109, 69)]

assembly brooder {
    box = finger_box(length=500 mm, depth=350 mm, height=300 mm, thickness=t,
                     finger=25 mm, closed=true)

    # the front: the window and the pane's screw holes
    hole window {
        opening = Rectangle(center=(0, 0), width=200, height=120)
        for p in screw_at {
            s = Circle(center=p, diameter=4.5)
        }
    }
    At(window.opening.center, box.front.outline.center, dy=30)
    CutInto(window, box.front)

    drawing label {
        word = Text("CHICKS", position=(0, 0), size=30, valign="middle",
                    font="sans:Bold", fill=true)
    }
    At(label.word.position, box.front.outline.center, dy=-95)
    CutInto(label, box.front)

    # the lid: vents and the cord hole
    hole vent {
        c = Circle(center=(0, 0), diameter=8)
    }
    vents = GridPattern(vent, 5, 9, (30, 30))
    At(vent.c.center, box.lid.outline.center, dx=-120, dy=-60)
    CutInto(vent, box.lid)

    hole cord {
        c = Circle(center=(0, 0), diameter=40)
    }
    At(cord.c.center, box.lid.outline.center, dx=-200)
    CutInto(cord, box.lid)

    # the clear pane, 3 mm acrylic
    solid pane {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, 0), width=236, height=156, corner_radius=6)
        hole screws {
            for p in screw_at {
                s = Circle(center=p, diameter=4.5)
            }
        }
    }
    RightOf(pane, box, gap=10)
    AlignTop(pane, box)

    assert len(vents) == 45, "45 vent holes"
    assert box.lid.bb.left + 50 mm == cord.c.center.x, "cord hole 50 mm from the lid's left end"
    assert box.front.bb.width == 500 mm and box.front.bb.height == 300 mm, "500 long, 300 tall"
    assert box.left.bb.height == 350 mm, "350 mm deep"
    assert distance(label, window) >= 10 mm, "the name clears the window and its screws"
    assert window.bb.bottom >= box.front.core.bb.bottom and window.bb.top <= box.front.core.bb.top,
        "window clear of the finger joints"
    assert distance(cord, vents) >= 20 mm, "cord hole clear of the vents"
    assert pane.plate.bb.width - window.opening.bb.width == 36 mm, "pane overlaps the window 18 mm a side"
}
