# Request (music): a stand for my daughter's soprano recorder, 6 mm ply, two pieces crossed.
# The upright: a foot bar 100 x 20 mm, a shoulder tapering from 50 to 14 mm over 30 mm, and a
# peg 11 mm wide with a round top that goes up into the recorder's foot, its tip 130 mm above
# the table. The cross bar: 100 x 20 mm. The two bars are cross-halved at their middles (each
# slot 10 mm deep, 0.2 mm play). Both bars stand on two feet: an arch cut from the bottom edge
# each side of the middle (a circle r17 centred 28 mm out and 12 mm below the edge).
# "MAYA" engraved filled, bold, 7 mm, reading up the peg.

import "std/joints.aidl"

thickness 6 mm
ply = 6 mm

assembly stand {
    solid upright {
        foot = Rectangle(center=(0, 10), width=100, height=20)
        shoulder = Trapezoid(center=(0, 35), bottom_width=50, top_width=14, height=30)
        peg = Slot(start=(0, 45), end=(0, 130 mm - 5.5 mm), width=11)
        x = cross_halving(depth=10 mm, thickness=ply, clearance=0.2 mm, rotation=180 deg,
                          cx=0 mm, cy=0 mm)
        hole arch_l { c = Circle(center=(-28, -12), radius=17) }
        hole arch_r { c = Circle(center=(28, -12), radius=17) }
        drawing name {
            t = Text("MAYA", (0, 90), size=7, font="sans:Bold", fill=true, rotation=90 deg,
                     valign="middle")
        }
    }

    solid bar {
        body = Rectangle(center=(0, 10), width=100, height=20)
        x = cross_halving(depth=10 mm, thickness=ply, clearance=0.2 mm, cx=0 mm, cy=20 mm)
        hole arch_l { c = Circle(center=(-28, -12), radius=17) }
        hole arch_r { c = Circle(center=(28, -12), radius=17) }
    }

    # 3D: the upright in the x-z plane, the bar in the y-z plane, crossing at the middle
    Place(upright, position=(0, ply / 2, 0), rotation=(90 deg, 0, 0))
    Place(bar, position=(-ply / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # on the sheet
    RightOf(bar, upright, gap=6)
    AlignBottom(bar, upright)

    assert upright.peg.width == 11 mm, "peg 11 wide"
    assert upright.peg.bb.top - upright.foot.bb.bottom == 130 mm, "peg tip 130 above the table"
    assert upright.foot.bb.width == 100 mm and bar.body.bb.width == 100 mm, "feet 100 long"
    assert upright.x.depth + bar.x.depth == 20 mm, "the halvings meet through the 20 mm bars"
    assert upright.name.t.bb.width < 11 mm, "the name fits across the peg"
}
