# Headphone hanger that clamps over a desk edge, side profile cut from 8 mm
# plywood. A C-clamp: a back spine 8 mm wide, two jaws 60 mm long and 8 mm thick
# with a 25.5 mm opening between them for a 25 mm desk top (the desk is to the
# right). The spine runs on 40 mm below the lower jaw, where a U-shaped hook
# starts: a 10 mm wide band bent round a 22 mm radius (to its center line), half a
# circle, its free end pointing up under the desk. The C's two inner corners
# are rounded 3 mm.

units mm
thickness 8 mm

param desk = 25 mm, min = 15 mm, max = 45 mm
param jaw = 60 mm, min = 40 mm, max = 90 mm

solid hanger {
    spine = Rectangle(bottom_left=(0, -40), width=8, height=desk + 0.5 + 16 + 40)
    top_jaw = Rectangle(bottom_left=(0, 33.5), width=jaw, height=8)
    low_jaw = Rectangle(bottom_left=(0, 0), width=jaw, height=8)
    AlignTop(top_jaw, spine)
    AlignLeft(top_jaw, spine)
    Below(low_jaw, top_jaw, gap=desk + 0.5)
    AlignLeft(low_jaw, spine)

    hook = ArcSlot(center=(26, -40), radius=22, start_angle=180 deg, end_angle=360 deg, width=10)
    Coincident(hook.start, spine.bottom.midpoint)

    Fillet([spine.right, top_jaw.bottom], 3)
    Fillet([spine.right, low_jaw.top], 3)
}
