# Request: a tombola (raffle) drum for the village fete. The drum is a 3 mm ply cylinder
# 160 mm across and 200 long: a flex box (base and lid discs with glued lips, a wall bent
# round on living hinges) lying on its side on an M8 threaded rod through 8 mm clearance
# holes in the middle of both discs and both lips; the lid comes off (after the wing nut)
# to fill it. The lid is engraved "VILLAGE FETE 2026" round a 55 mm circle, 9 mm letters.
# The stand is 6 mm ply: two uprights, trapezoids 220 wide at the floor, 50 at the top,
# 200 tall, top corners rounded 10 mm, the axle's 8 mm clearance hole 130 mm up, "TOMBOLA"
# engraved filled (bold, 18 mm) across each, baseline 60 mm up; their inner faces 208 mm
# apart (4 mm for washers each end of the drum); a stretcher 30 tall, 10 mm above the floor,
# with one 16 mm through-tenon into each upright, glued. A crank 6 mm: a round-ended arm
# 24 wide, 70 mm between its M8 nut trap (on the rod) and a 10 mm hole for a dowel handle.

import "std/boxes.aidl"
import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

drum_d = 160 mm
drum_l = 200 mm
T = 6 mm
axle_z = 130 mm
inner = 208 mm           # between the uprights' inner faces
str_low = 10 mm
str_h = 30 mm

def upright() -> solid {
    body = Trapezoid(center=(0, 100), bottom_width=220, top_width=50, height=200)
    axle = clearance_hole(size=8, cx=0, cy=axle_z)
    mortise = tab_and_slot(part="slot", length=str_h, thickness=T, tabs=1, tab=16 mm, screw=0,
                           rotation=90 deg, cx=0, cy=str_low + str_h / 2)
    drawing word {
        t = Text("TOMBOLA", position=(0, 60), size=18, font="sans:Bold", fill=true)
    }
    Fillet(at=[body.top_left, body.top_right], radius=10)
}

assembly tombola {
    drum = flex_box(length=drum_d, width=drum_d, height=drum_l, radius=drum_d / 2, thickness=3 mm)

    hole axle_b { c = Circle(center=(0, 0), diameter=9) }
    hole axle_l { c = Circle(center=(0, 0), diameter=9) }
    hole axle_lb { c = Circle(center=(0, 0), diameter=9) }
    hole axle_ll { c = Circle(center=(0, 0), diameter=9) }
    CenterInside(axle_b, drum.base)
    CutInto(axle_b, drum.base)
    CenterInside(axle_l, drum.lid)
    CutInto(axle_l, drum.lid)
    CenterInside(axle_lb, drum.lip[0])
    CutInto(axle_lb, drum.lip[0])
    CenterInside(axle_ll, drum.lip[1])
    CutInto(axle_ll, drum.lip[1])

    drawing fete {
        ring = Circle(center=(0, 0), radius=55, construction=true)
        t = Text("VILLAGE FETE 2026", along=ring, size=9)
    }
    AlignCenterX(fete.ring.center, drum.lid)
    AlignCenterY(fete.ring.center, drum.lid)
    CutInto(fete, drum.lid)

    left = upright()
    right = upright()

    solid stretcher {
        body = Rectangle(center=(0, str_low + str_h / 2), width=inner, height=str_h)
        end_r = Rectangle(center=(inner / 2 + T / 2, str_low + str_h / 2), width=T, height=str_h)
        end_l = Rectangle(center=(-inner / 2 - T / 2, str_low + str_h / 2), width=T, height=str_h)
        jr = tab_and_slot(part="tab", length=str_h, thickness=T, tabs=1, tab=16 mm, screw=0,
                          rotation=-90 deg, cx=inner / 2 + T, cy=str_low + str_h / 2)
        jl = tab_and_slot(part="tab", length=str_h, thickness=T, tabs=1, tab=16 mm, screw=0,
                          rotation=90 deg, cx=-inner / 2 - T, cy=str_low + str_h / 2)
    }

    solid crank {
        arm = Slot(start=(0, 0), end=(70, 0), width=24)
        nut = nut_trap(size=8, cx=0, cy=0)
        hole handle { c = Circle(center=(70, 0), diameter=10) }
        Rigid(self)
    }

    # on the sheet
    RightOf(left, drum, gap=10)
    AlignTop(left, drum)
    RightOf(right, left, gap=10)
    AlignTop(right, drum)
    Below(stretcher, left, gap=10)
    AlignLeft(stretcher, left)
    Below(crank, stretcher, gap=10)
    AlignLeft(crank, stretcher)

    # assembled: the rod along x at height axle_z, the drum lying on it
    Place(drum, rotation=(0, 90 deg, 0), position=(-drum_l / 2, 0, axle_z))
    Place(left, position=(-inner / 2, 0, 0), face="left", up="up")
    Place(right, position=(inner / 2, 0, 0), face="right", up="up")
    Place(stretcher, position=(0, T / 2, 0), face="front", up="up")
    Place(crank, position=(inner / 2 + T + 2, 0, axle_z), face="right", up="up")

    # the request's numbers
    assert drum.base.bb.width == 160 mm, "drum 160 across"
    assert drum.height == 200 mm, "drum 200 long"
    assert left.body.bottom_width == 220 mm and left.body.top_width == 50 mm, "uprights 220 / 50"
    assert left.body.height == 200 mm, "uprights 200 tall"
    assert left.axle.c.center.y - left.body.bb.bottom == 130 mm, "axle 130 up"
    assert left.word.t.position.y - left.body.bb.bottom == 60 mm, "TOMBOLA 60 up"
    assert left.word.bb.width < 160 mm, "TOMBOLA inside the upright"
    assert inner - drum_l == 8 mm, "4 mm for washers each end"
    assert axle_z - drum_d / 2 > str_low + str_h + 5 mm, "drum clears the stretcher"
    assert stretcher.body.height == 30 mm, "stretcher 30 tall"
    assert crank.arm.width == 24 mm and crank.arm.length - 24 mm == 70 mm, "crank 70 between holes"
}
