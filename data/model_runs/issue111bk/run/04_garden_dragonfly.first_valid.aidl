# Request: a dragonfly on a stake for the flower bed, cut from 6 mm outdoor acrylic. The body
# seen from the side, 260 mm from head to tail tip: a round head 26 mm across, a thorax 70 mm
# long with a flat top, a tail tapering from 18 mm to 6 mm; engraved eye and tail rings. Two
# wing pieces lie across the thorax's top, each one tenon (20 mm, one per piece, 35 mm apart)
# up through a slot in the piece's hub: front wings 230 mm tip to tip, hind wings 210 mm, both
# 26 mm chord, each wing with four oval windows 20 mm apart. A stake 400 mm long (30 mm wide
# at the top, 16 mm below, pointed) joined under the thorax with a sliding dovetail
# (one tail, 30 mm long, 10 mm deep), so the stake can be cut from an offcut.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
H = 400 mm   # height of the body's frame origin above the ground line (for the 3D view)

def wing_pair(reach=115 mm) -> solid {
    # seen from above: x along the body (head +x), y across; the hub's slot at (0, 0)
    hub = Circle(center=(0, 0), radius=14)
    wing = Ellipse(center=(0, (reach - 3 mm) / 2), rx=13, ry=(reach + 3 mm) / 2)
    axis = Line((-20, 0), (20, 0), construction=true)
    other = Mirrored(wing, axis)
    hole window {
        o = Ellipse(center=(0, 30), rx=5, ry=7)
    }
    cells = LinearPattern(window, 4, (0, 20))
    cells_other = Mirrored(cells, axis)
    mortise = tab_and_slot(part="slot", length=35, thickness=t, tabs=1, tab=20 mm, screw=0,
                           rotation=0 deg, cx=0, cy=0)
}

assembly dragonfly {
    solid body {
        # seen from the side: x along the body (head +x), y up; thorax shoulder at y = 12
        thorax = RoundedRectangle(center=(55, 3), width=70, height=30,
                                  corner_radii=[0, 0, 10, 10])
        head = Circle(center=(100, 0), diameter=26)
        tail = Hull(Circle(center=(25, 0), diameter=18), Circle(center=(-144, 0), diameter=6))
        hind_tenon = tab_and_slot(part="tab", length=35, thickness=t, tabs=1, tab=20 mm,
                                  screw=0, rotation=0 deg, cx=37.5, cy=18)
        front_tenon = tab_and_slot(part="tab", length=35, thickness=t, tabs=1, tab=20 mm,
                                   screw=0, rotation=0 deg, cx=72.5, cy=18)
        socket = dovetail(part="socket", length=30, depth=10, tails=1, angle=10 deg,
                          clearance=0.1 mm, cx=55, cy=-12)
        drawing marks {
            eye = Circle(center=(106, 4), radius=4, fill=true)
            for i in range(8) {
                ring = Line((5 - i * 18, -3), (5 - i * 18, 3))
            }
        }
        Fixed(thorax)
        assert head.bb.right - tail.bb.left == 260 mm, "260 head to tail"
        assert head.diameter == 26 mm, "head 26"
        assert thorax.width == 70 mm, "thorax 70 long"
        assert front_tenon.cx - hind_tenon.cx == 35 mm, "tenons 35 apart"
    }

    solid stake {
        # the dovetail's root line at y = 0, the tail reaching up to y = 10
        body = Polygon([(-15, 10), (15, 10), (15, -20), (8, -40), (8, -360), (0, -390),
                        (-8, -360), (-8, -40), (-15, -20)])
        tail = dovetail(part="tail", length=30, depth=10, tails=1, angle=10 deg, cx=0, cy=0)
        Fixed(body)
        assert body.bb.height == 400 mm, "stake 400 long"
        assert body.bb.width == 30 mm, "30 wide at the top"
    }

    front_wings = wing_pair(reach=115 mm)
    hind_wings = wing_pair(reach=105 mm)

    # flat on the sheet
    LeftOf(stake, body, gap=10)
    AlignTop(stake, body)
    RightOf(front_wings, body, gap=10)
    AlignTop(front_wings, body)
    RightOf(hind_wings, front_wings, gap=10)
    AlignTop(hind_wings, front_wings)

    # in 3D: x along the body, y across, z up; the body stands in the plane y = 0
    Place(body, position=(0, t / 2, H), rotation=(90 deg, 0, 0))
    Place(stake, position=(55, t / 2, H - 12), rotation=(90 deg, 0, 0))
    Place(front_wings, position=(72.5, 0, H + 12))
    Place(hind_wings, position=(37.5, 0, H + 12))

    assert front_wings.bb.height == 230 mm, "front wings 230 tip to tip"
    assert hind_wings.bb.height == 210 mm, "hind wings 210 tip to tip"
    assert len(front_wings.cells) == 4, "four windows a wing"
}
