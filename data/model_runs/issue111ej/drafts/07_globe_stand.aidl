# Request (science): a stand for a 200 mm classroom globe (its axle pins 3 mm), 3 mm ply,
# tilted at the Earth's 23.4 deg. A half meridian ring 12 mm wide on a 110 mm radius (4 mm clear
# of the globe), round-ended at the poles, each end with a 3.2 mm pin hole on the axis. The
# ring sits cross-halved on an upright: a trapezoid 60 mm wide at the foot, 24 at the top, 70
# above the base, with two 12 mm glued tenons into a base disc of 75 mm radius; the halving
# 6 mm into each, at the ring's lowest point. "AXIAL TILT 23.4°" engraved filled round the top
# of the base (sans, 7 mm, on a 60 mm circle). Parts cut side by side 8 mm apart; stood up
# in the 3D view.

units mm
thickness 3 mm

import "std/joints.aidl"

globe_r = 100 mm
ring_r = 110 mm
ring_w = 12 mm
tilt = 23.4 deg
post_h = 70 mm
halving = ring_w / 2
centre_z = 3 mm + post_h + ring_r - ring_w / 2    # the globe's centre above the floor

assembly globe_stand {
    solid base {
        disc = Circle(center=(0, 0), radius=75)
        mortise = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                               screw=0, cx=0 mm, cy=0 mm)
        drawing legend {
            ring = Circle(center=(0, 0), radius=60, construction=true)
            t = Text("AXIAL TILT 23.4°", along=ring, size=7, font="sans", fill=true)
        }
        Fixed(disc)
    }

    solid upright {
        post = Trapezoid(center=(0, (post_h + 3) / 2), bottom_width=60, top_width=24,
                         height=post_h + 3)
        tenons = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        notch = cross_halving(depth=halving, thickness=3 mm, cx=0 mm, cy=post_h + 3)
        Fixed(post)
    }

    solid meridian {
        ring = ArcSlot(center=(0, 0), radius=ring_r, start_angle=90 deg + tilt,
                       end_angle=270 deg + tilt, width=ring_w)
        hole north { c = Circle(center=(-44, 101), diameter=3.2) }
        hole south { c = Circle(center=(44, -101), diameter=3.2) }
        Coincident(north.c.center, ring.start)
        Coincident(south.c.center, ring.end)
        notch = cross_halving(depth=halving, thickness=3 mm, cx=0 mm, cy=-(ring_r + ring_w / 2),
                              rotation=180 deg)
        Fixed(ring)
    }

    RightOf(upright, base, gap=8)
    AlignBottom(upright, base)
    RightOf(meridian, upright, gap=8)
    AlignBottom(meridian, base)

    Place(base, position=(0, 0, 0), face="up")
    Place(upright, position=(0, 1.5, 0), face="front", up="up")
    Place(meridian, position=(-1.5, 0, centre_z), face="right", up="up")

    # the request's numbers
    assert abs(meridian.ring.radius - 110 mm) < 0.001 mm and abs(meridian.ring.width - 12 mm) < 0.001 mm, "ring 12 wide on R110"
    assert meridian.ring.inner_radius - 200 mm / 2 >= 4 mm - 0.001 mm, "4 mm clear of the globe"
    assert abs(degrees(atan2(meridian.north.c.center.x, meridian.north.c.center.y)) + 23.4) < 0.01, "axis tilted 23.4 deg"
    assert abs(distance(meridian.north.c.center, meridian.south.c.center) - 2 * 110 mm) < 0.01 mm, "poles opposite"
    assert abs(upright.post.bottom_width - 60 mm) < 0.001 mm and abs(upright.post.top_width - 24 mm) < 0.001 mm, "post 60 / 24"
    assert abs(upright.post.height - 3 mm - 70 mm) < 0.001 mm, "70 above the base"
    assert abs(base.disc.radius - 75 mm) < 0.001 mm, "base R75"
    assert abs(upright.notch.depth + meridian.notch.depth - 12 mm) < 0.001 mm, "halvings make the ring's width"
    assert distance(base.legend, base.mortise) >= 5 mm, "legend clear of the mortises"
}
