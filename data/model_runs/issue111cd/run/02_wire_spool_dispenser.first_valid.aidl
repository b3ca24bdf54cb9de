# Request (electronics): a bench dispenser for six spools of hookup wire, 3 mm ply.
# Spools 54 mm across and 25 mm wide, all on one 8 mm dowel through two end plates.
# Base 186 x 96 mm, corners r5. End plates 80 mm deep, standing 65 mm above the base, top
# corners rounded r30, the dowel hole 8.4 mm at 40 mm above the base, centred in the depth;
# each end plate glued into the base by two 15 mm tabs. Between the end plates (160 mm apart
# inside) a front fence 45 mm tall, 36 mm in front of the dowel, glued in by three 20 mm tabs,
# with a 4 mm eyelet 30 mm up in front of each spool and the colour engraved under it
# (RED, BLACK, YELLOW, GREEN, BLUE, WHITE). "HOOKUP WIRE" engraved on the base in front of it.

import "std/joints.aidl"

thickness 3 mm
ply = 3 mm

inner = 160 mm      # between the end plates
spool_d = 54 mm
spool_w = 25 mm
axle_h = 40 mm      # dowel above the base
fence_y = -36 mm    # fence centre, in front of the dowel
colours = ["RED", "BLACK", "YELLOW", "GREEN", "BLUE", "WHITE"]

def spool_x(i) = -inner / 2 + inner / 12 + i * inner / 6

def end_plate() -> solid {
    # frame: x along the depth, y up; the tabs' tips at y = -3 (flush under the base)
    body = RoundedRectangle(center=(0, (65 mm - ply) / 2), width=80, height=65 + ply,
                            corner_radii=[30, 30, 0, 0])
    t = tab_and_slot(part="tab", length=80 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=-ply)
    hole axle { c = Circle(center=(0, axle_h), diameter=8.4) }
}

assembly dispenser {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=186, height=96, corner_radius=5)
        sl = tab_and_slot(part="slot", length=80 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=-(inner + ply) / 2, cy=0 mm)
        sr = tab_and_slot(part="slot", length=80 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=(inner + ply) / 2, cy=0 mm)
        sf = tab_and_slot(part="slot", length=inner, thickness=ply, tabs=3, tab=20 mm, screw=0,
                          cx=0 mm, cy=fence_y)
        drawing title { t = Text("HOOKUP WIRE", (0, -43), size=5, valign="middle") }
    }

    solid fence {
        body = Rectangle(center=(0, (45 mm - ply) / 2), width=inner, height=45 + ply)
        t = tab_and_slot(part="tab", length=inner, thickness=ply, tabs=3, tab=20 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-ply)
        hole eyes {
            for i in range(6) { e = Circle(center=(spool_x(i), 30), diameter=4) }
        }
        drawing names {
            for i in range(6) { n = Text(colours[i], (spool_x(i), 18), size=3.5) }
        }
    }

    left = end_plate()
    right = end_plate()

    # 3D: base flat; end plates in the y-z plane ((x, y, z) -> (z, x, y)); fence in the x-z plane
    Place(base, position=(0, 0, 0), rotation=(0, 0, 0))
    Place(left, position=(-inner / 2 - ply, 0, ply), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(inner / 2, 0, ply), rotation=(90 deg, 0, 90 deg))
    Place(fence, position=(0, fence_y + ply / 2, ply), rotation=(90 deg, 0, 0))

    # on the sheet
    Below(fence, base, gap=6)
    AlignLeft(fence, base)
    RightOf(left, base, gap=6)
    AlignTop(left, base)
    RightOf(right, left, gap=6)
    AlignTop(right, left)

    assert len(colours) == 6, "six spools"
    assert inner >= 6 * 25 mm + 6 mm, "six 25 mm spools fit between the end plates"
    assert axle_h - 54 mm / 2 >= 10 mm, "a 54 mm spool clears the base"
    assert -fence_y - ply / 2 - 54 mm / 2 >= 5 mm, "the spools clear the fence"
    assert left.axle.c.center.y - left.bb.bottom - ply == 40 mm, "dowel 40 above the base"
    assert base.body.bb.width == 186 mm and base.body.bb.height == 96 mm, "base 186 x 96"
    assert fence.body.bb.height - ply == 45 mm, "fence 45 tall"
}
