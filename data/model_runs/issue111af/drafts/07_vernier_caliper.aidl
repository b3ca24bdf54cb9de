# Request (science class): a working vernier caliper in 3 mm clear acrylic, reading to 0.1 mm,
# 5 parts:
# - the beam: 200 x 20 mm with a fixed jaw 15 mm wide reaching 40 mm below it at the left end;
#   a main scale engraved along its top edge, 0-150 mm: 1 mm ticks 3 mm long, 5 mm ticks 4.5 mm,
#   10 mm ticks 6 mm, numbered 0-15 (cm); its zero 5 mm right of the jaw's inner face; a 5 mm
#   hanging hole 7 mm from the right end; "VERNIER 0.1 mm" engraved under the numbers;
# - the slider, a sandwich round the beam: front and back plates 50 x 46 mm (12 mm below the
#   beam, 14 above) with a jaw 15 wide reaching 40 below the beam, glued to two 3 mm spacers
#   (above and below the beam, 0.2 mm clear of it) and held by 4 M2 screws (2.2 mm holes);
#   the front plate has a 44 x 14 mm window over the main scale and, on the window's top
#   edge, the vernier: 10 divisions in 9 mm (ticks 0.9 mm apart, 2.5 mm long, 0/5/10 4 mm long,
#   numbered 0, 5, 10), its zero 5 mm right of the slider jaw's inner face.

units mm
thickness 3 mm

beam_l = 200 mm
beam_h = 20 mm
jaw_w = 15 mm
jaw_l = 40 mm
zero = 5 mm                # each scale's zero from its jaw's inner face
slider_w = 50 mm
below = 12 mm
above = 14 mm
clear = 0.2 mm
m2 = 2.2 mm
screw_pts = [(25, -6), (44, -6), (25, beam_h + 9), (44, beam_h + 9)]

def tick(i) = 6 mm if i % 10 == 0 else (4.5 mm if i % 5 == 0 else 3 mm)

def slider_plate(front=false) -> solid {
    plate = Rectangle(bottom_left=(0, -below), width=slider_w, height=below + beam_h + above)
    jaw = Rectangle(bottom_left=(0, -jaw_l), width=jaw_w, height=jaw_l - below)
    hole screws {
        for p in screw_pts { s = Circle(center=p, diameter=m2) }
    }
    if front {
        hole window { w = Rectangle(center=(25, 13), width=44, height=14) }
        drawing vernier {
            for j in range(11) {
                v = Line((zero + j * 0.9 mm, beam_h + 0.5), (zero + j * 0.9 mm, beam_h + 0.5 + (4 if j % 5 == 0 else 2.5)))
            }
            n0 = Text("0", position=(zero, beam_h + 6), size=2, valign="middle")
            n5 = Text("5", position=(zero + 4.5 mm, beam_h + 6), size=2, valign="middle")
            n10 = Text("10", position=(zero + 9 mm, beam_h + 6), size=2, valign="middle")
        }
    }
    Fixed(plate)
}

assembly caliper {
    solid beam {
        bar = Rectangle(bottom_left=(-jaw_w, 0), width=beam_l, height=beam_h)
        jaw = Rectangle(bottom_left=(-jaw_w, -jaw_l), width=jaw_w, height=jaw_l)
        hole hang { c = Circle(center=(beam_l - jaw_w - 7, beam_h / 2), diameter=5) }
        drawing scale {
            for i in range(151) {
                l = Line((zero + i * 1 mm, beam_h), (zero + i * 1 mm, beam_h - tick(i)))
            }
            for k in range(16) {
                n = Text(str(k), position=(zero + k * 10 mm, 10), size=3, valign="middle")
            }
            name = Text("VERNIER 0.1 mm", position=(80, 4), size=2.5, valign="middle")
        }
        Fixed(bar)
    }

    front = slider_plate(front=true)
    back = slider_plate()

    solid top_spacer {
        r = Rectangle(bottom_left=(0, beam_h + clear), width=slider_w, height=above - clear)
        hole screws {
            s1 = Circle(center=screw_pts[2], diameter=m2)
            s2 = Circle(center=screw_pts[3], diameter=m2)
        }
        Fixed(r)
    }
    solid bottom_spacer {
        r = Rectangle(bottom_left=(0, -below), width=slider_w, height=below - clear)
        jaw = Rectangle(bottom_left=(0, -jaw_l), width=jaw_w, height=jaw_l - below)
        hole screws {
            s1 = Circle(center=screw_pts[0], diameter=m2)
            s2 = Circle(center=screw_pts[1], diameter=m2)
        }
        Fixed(r)
    }

    # laid out flat for cutting: the slider's parts in a row under the beam
    Below(front, beam, gap=8)
    AlignLeft(front, beam)
    RightOf(back, front, gap=8)
    AlignTop(back, front)
    RightOf(bottom_spacer, back, gap=8)
    AlignTop(bottom_spacer, back)
    RightOf(top_spacer, bottom_spacer, gap=8)
    AlignTop(top_spacer, bottom_spacer)

    assert beam.bar.width == 200 mm and beam.bar.height == 20 mm, "beam 200 x 20"
    assert beam.jaw.width == 15 mm and beam.jaw.height - beam.bar.height == 40 mm - 20 mm, "jaw 40 below the beam"
    assert len(beam.scale.l) == 151, "0-150 mm"
    assert len(beam.scale.n) == 16, "numbered 0-15"
    assert len(front.vernier.v) == 11, "10 divisions"
    assert abs(front.vernier.v[10].start.x - front.vernier.v[0].start.x - 9 mm) < 1e-6 mm, "in 9 mm"
    assert beam.scale.l[0].start.x - beam.jaw.bb.right == 5 mm, "main zero 5 from the jaw"
    assert front.vernier.v[0].start.x - front.plate.bb.left == 5 mm, "vernier zero 5 from the slider jaw"
    assert front.plate.height == 46 mm and front.plate.width == 50 mm, "slider 50 x 46"
    assert front.window.w.width == 44 mm and front.window.w.height == 14 mm, "window 44 x 14"
    assert top_spacer.r.bb.bottom - front.plate.bb.bottom == 12 mm + 20 mm + 0.2 mm, "top spacer 0.2 clear of the beam"
}
