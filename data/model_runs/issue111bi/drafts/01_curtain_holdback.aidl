# Request: a curtain holdback for my living-room window, cut twice (one each side), in 6 mm
# birch ply. Each holdback is three glued parts:
# - a wall plate 40 mm wide x 100 mm tall with 6 mm rounded corners, two countersunk holes for
#   M4 wood screws (8 mm heads) 70 mm apart on its centre line, and a mortise in the middle
#   for the arm;
# - an arm that holds the curtain 90 mm out from the plate: 30 mm tall at the wall, tapering
#   to 20 mm at the front (flat top, sloping underside), with a 20 mm tenon into the plate
#   and a 12 mm tenon into the rosette;
# - a 60 mm rosette disc on the arm's end that stops the curtain sliding off: a mortise at
#   its centre, six petal-shaped openings round it and an engraved ring 3 mm in from the rim.

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/fasteners.aidl"

param reach = 90 mm, min = 60, max = 140   # the arm between plate and rosette

T = 6 mm   # the ply

assembly holdback {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=40, height=100, corner_radius=6)
        top_screw = clearance_hole(size=4, cx=0, cy=35)
        bottom_screw = clearance_hole(size=4, cx=0, cy=-35)
        Countersink([top_screw, bottom_screw], diameter=8)
        mortise = tab_and_slot(part="slot", length=30, thickness=T, tabs=1, tab=20, screw=0,
                               rotation=90 deg, cx=0, cy=0)
    }

    # side view: x out from the plate's face (0) to the rosette's back (reach), y up;
    # the tenons reach T past each end
    solid arm {
        body = Polygon([(-T, 15), (reach + T, 15), (reach + T, -5), (-T, -15)])
        wall_tenon = tab_and_slot(part="tab", length=30, thickness=T, tabs=1, tab=20, screw=0,
                                  rotation=90 deg, cx=-T, cy=0)
        disc_tenon = tab_and_slot(part="tab", length=20, thickness=T, tabs=1, tab=12, screw=0,
                                  rotation=-90 deg, cx=reach + T, cy=5)
    }

    solid rosette {
        disc = Circle(center=(0, 0), diameter=60)
        mortise = tab_and_slot(part="slot", length=20, thickness=T, tabs=1, tab=12, screw=0,
                               rotation=90 deg, cx=0, cy=0)
        hole petal {
            p = Ellipse(center=(18, 0), rx=6, ry=3)
        }
        petals = CircularPattern(petal, 6, (0, 0))
        drawing ring {
            r = Circle(center=(0, 0), radius=27)
        }
    }

    # on the sheet: side by side
    RightOf(arm, plate, gap=10)
    AlignCenterY(arm, plate)
    RightOf(rosette, arm, gap=10)
    AlignCenterY(rosette, arm)

    # in 3D: the wall is the plane y = 0, the arm sticks out toward -y
    Place(plate, position=(0, 0, 0), rotation=(90 deg, 0, 0))
    Place(arm, position=(3, -T, 0), rotation=(90 deg, 0, -90 deg))
    Place(rosette, position=(0, -(T + reach), 5), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert plate.body.bb.width == 40 mm and plate.body.bb.height == 100 mm, "plate 40 x 100"
    assert plate.top_screw.c.center.y - plate.bottom_screw.c.center.y == 70 mm, "screws 70 apart"
    assert arm.body.bb.width - 2 * T == 90 mm, "curtain space 90 mm"
    assert arm.body.points[0].y - arm.body.points[3].y == 30 mm, "arm 30 tall at the wall"
    assert arm.body.points[1].y - arm.body.points[2].y == 20 mm, "arm 20 tall at the front"
    assert rosette.disc.diameter == 60 mm, "rosette 60"
    assert len(rosette.petals) == 6, "six petals"
    assert rosette.disc.radius - rosette.ring.r.radius == 3 mm, "ring 3 mm in"
    assert plate.mortise.tab == arm.wall_tenon.tab and rosette.mortise.tab == arm.disc_tenon.tab,
        "mortises fit the tenons"
}
