# A closed finger-jointed box, 80 x 80 x 50 mm outside, 3 mm plywood,
# with a 20 mm round hole in the middle of the lid.
# Six finger panels laid out flat as a net; each is placed in 3D with Place.
import "std/joints.aidl"

param L = 80 mm   # outside length (x)
param D = 80 mm   # outside depth (y)
param H = 50 mm   # outside height (z)
param t = 3 mm
param hole_d = 20 mm
param finger = 10 mm

s = 70 mm         # spacing of the panels in the flat layout

thickness 3 mm

assembly box {
    # bottom and lid: slots along front and back, fingers at the sides
    bottom = finger_panel(width=L, height=D, thickness=t, finger=finger,
                          bottom="slots", right="fingers", top="slots", left="fingers",
                          cx=0 mm, cy=0 mm)
    solid lid {
        panel = finger_panel(width=L, height=D, thickness=t, finger=finger,
                             bottom="slots", right="fingers", top="slots", left="fingers",
                             cx=0 mm, cy=2 * s)
        hole bore {
            c = Circle(center=(0, 2 * s), diameter=hole_d)
        }
        Concentric(bore.c, panel.outline)
    }
    # front and back: fingers on every edge
    front = finger_panel(width=L, height=H, thickness=t, finger=finger, cx=0 mm, cy=-s)
    back = finger_panel(width=L, height=H, thickness=t, finger=finger, cx=0 mm, cy=s)
    # left and right (drawn with the height along x): slots all round
    left = finger_panel(width=H, height=D, thickness=t, finger=finger,
                        bottom="slots", right="slots", top="slots", left="slots",
                        cx=-s, cy=0 mm)
    right = finger_panel(width=H, height=D, thickness=t, finger=finger,
                         bottom="slots", right="slots", top="slots", left="slots",
                         cx=s, cy=0 mm)
    Fixed(bottom)
    Fixed(lid)
    Fixed(front)
    Fixed(back)
    Fixed(left)
    Fixed(right)

    # assembled: the box stands on z = 0, centered on x = y = 0
    Place(bottom, position=(0, 0, 0))
    Place(lid, position=(0, -2 * s, H - t))
    Place(front, rotation=(90 deg, 0, 0), position=(0, -D / 2 + t, H / 2 + s))
    Place(back, rotation=(90 deg, 0, 0), position=(0, D / 2, H / 2 - s))
    Place(left, rotation=(0, 90 deg, 0), position=(-L / 2, 0, H / 2 - s))
    Place(right, rotation=(0, 90 deg, 0), position=(L / 2 - t, 0, H / 2 + s))
}
