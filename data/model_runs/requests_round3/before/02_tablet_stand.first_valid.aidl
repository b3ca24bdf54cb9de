# A tablet stand from two pieces of 4 mm plywood that slot together at right
# angles (cross-halving joint). Kerf 0.2 mm.
# Back piece 150 x 120 mm, front support 120 x 100 mm.
import "std/joints.aidl"

param t = 4 mm
param back_w = 150 mm
param back_h = 120 mm
param sup_w = 120 mm
param sup_h = 100 mm

thickness 4 mm
kerf 0.2 mm

# the two slots together span the support's height: half in each piece
slot_depth = sup_h / 2

assembly stand {
    solid back {
        body = Rectangle(center=(0, 0), width=back_w, height=back_h)
        # slot up from the middle of the bottom edge
        joint = cross_halving(depth=slot_depth, thickness=t, rotation=90 deg,
                              cx=0 mm, cy=-back_h / 2)
    }
    solid support {
        body = Rectangle(center=(0, -150), width=sup_w, height=sup_h)
        # slot down from the middle of the top edge
        joint = cross_halving(depth=slot_depth, thickness=t, rotation=-90 deg,
                              cx=0 mm, cy=-150 mm + sup_h / 2)
    }
    Fixed(back.body)
    Fixed(support.body)
    Coincident(back.joint.cut.center, back.joint.cut.center)

    # assembled: the back stands across the support, both on the floor (z = 0)
    Place(back, rotation=(90 deg, 0, 0), position=(0, t / 2, back_h / 2))
    Place(support, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 150 mm + sup_h / 2))
}
