# Request: a Bohr model of a sodium atom for the science class display, 3 mm acrylic.
# A nucleus disc of 32 mm with "Na" (10 mm, filled) and "11p 12n" (3.5 mm) engraved; three
# shells as 3 mm rings of R32, R52 and R72 (centre lines), carrying 2, 8 and 1 electrons as
# 10 mm discs on the rings (shell 1 at 0 and 180 degrees, shell 2 from 22.5 degrees every
# 45, shell 3 at the top); four 3 mm spokes at 45, 135, 225 and 315 degrees join nucleus
# and rings. A neck 40 wide under the outer ring stands the model in a foot, 3 mm from the
# ring's bottom to the shoulder, on two 10 mm glued tenons. Foot 160 x 60, R6, the tenons'
# mortises 10 behind its middle, "SODIUM  2 . 8 . 1" filled (8 mm, bold) in front of them.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
radii = [32 mm, 52 mm, 72 mm]
counts = [2, 8, 1]
starts = [0 deg, 22.5 deg, 90 deg]
ring_w = 3 mm
electron_d = 10 mm
nucleus_d = 32 mm
neck_w = 40 mm
shoulder = -(72 mm + ring_w / 2 + 3 mm)     # the neck's shoulder, from the nucleus centre
mortise_y = 10 mm

assembly sodium {
    solid atom {
        nucleus = Circle(center=(0, 0), diameter=nucleus_d)
        for k in range(3) {
            ring = Shell(Circle(center=(0, 0), radius=radii[k] - ring_w / 2, construction=true),
                         ring_w)
        }
        for k in range(3) {
            for i in range(counts[k]) {
                e = Circle(center=(radii[k] * cos(starts[k] + i * 360 deg / counts[k]),
                                   radii[k] * sin(starts[k] + i * 360 deg / counts[k])),
                           diameter=electron_d)
            }
        }
        for j in range(4) {
            spoke = Rectangle(start=((nucleus_d / 2 - 1 mm) * cos(45 deg + j * 90 deg),
                                     (nucleus_d / 2 - 1 mm) * sin(45 deg + j * 90 deg)),
                              end=(radii[2] * cos(45 deg + j * 90 deg),
                                   radii[2] * sin(45 deg + j * 90 deg)),
                              width=3)
        }
        neck = Rectangle(corner=(-neck_w / 2, shoulder - t), opposite=(neck_w / 2, -radii[2]))
        tenons = tab_and_slot(part="tab", length=neck_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                              rotation=180 deg, cx=0 mm, cy=shoulder - t)
        drawing symbol {
            na = Text("Na", position=(0, 3), size=10, font="sans:Bold", valign="middle", fill=true)
            pn = Text("11p 12n", position=(0, -8), size=3.5, valign="middle")
        }
        assert len(e) == 3 and len(e[1]) == 8 and len(e[0]) + len(e[1]) + len(e[2]) == 11,
            "2, 8, 1 electrons: 11"
        assert distance(e[1][0], e[1][1]) >= 5 mm, "shell 2 electrons apart"
        assert distance(e[1][0], spoke[0]) >= 3 mm, "electrons clear of the spokes"
        assert distance(symbol, nucleus) >= 0 mm and symbol.bb.width <= nucleus_d - 6 mm,
            "symbol on the nucleus"
        assert ring[2].bb.bottom - shoulder == 3 mm, "3 mm from the ring to the shoulder"
    }

    solid foot {
        plate = RoundedRectangle(center=(0, 0), width=160, height=60, corner_radius=6)
        mortise = tab_and_slot(part="slot", length=neck_w, thickness=t, tabs=2, tab=10 mm,
                               screw=0, cx=0 mm, cy=mortise_y)
        drawing name {
            w = Text("SODIUM  2 . 8 . 1", position=(0, -12), size=8, font="sans:Bold",
                     valign="middle", fill=true)
        }
        assert distance(name, mortise) >= 5 mm, "name clear of the mortises"
        assert name.bb.width <= 150 mm, "name fits the foot"
    }

    Below(foot, atom, gap=8)
    AlignCenterX(foot, atom)

    Place(foot, position=(0, 0, 0), face="up")
    Place(atom, position=(0, mortise_y + t / 2, t - shoulder), face="front", up="up")
}
