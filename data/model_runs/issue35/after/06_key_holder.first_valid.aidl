import "std/plates.aidl"
import "std/fasteners.aidl"
# wall key holder: 150 x 50 board, five keyhole slots, two screw holes
solid holder {
    body = RoundedRectangle(center=(0, 0), width=150, height=50, corner_radius=5)
    Fixed(body)
    k = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-50, cy=-5)
    ks = LinearPattern(k, 5, (25, 0))
    At(k.head_hole.center, body.center, dx=-50, dy=-8)
    s1 = clearance_hole(size=4, cx=-67, cy=15)
    s2 = clearance_hole(size=4, cx=67, cy=15)
    At(s1.c.center, body.center, dx=-67, dy=15)
    At(s2.c.center, body.center, dx=67, dy=15)
}
