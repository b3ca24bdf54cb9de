# Guitar pick holder: a wall plate 90 mm wide x 70 mm tall, 5 mm corner radius, with
# three pick-shaped pockets (cut through, a pick rests in each on a backing board):
# each a rounded triangle 28 mm wide x 32 mm tall pointing down, corners rounded 5 mm,
# 30 mm apart centre to centre in a row, centred on the plate 5 mm below its centre;
# a keyhole (8 mm head) for hanging, 8 mm below the top edge in the middle.
import "std/plates.aidl"

solid holder {
    plate = RoundedRectangle(center=(0, 0), width=90, height=70, corner_radius=5)

    hole pick {
        tri = Triangle(center=(-30, -5), base=28, height=32, rotation=180)
        Fillet(5)
    }
    picks = LinearPattern(pick, 3, (30, 0))
    AlignCenterX(picks[1], plate)
    At(picks[1].tri.center, plate.center, dy=-5)

    hang = keyhole(head=8 mm)
    AlignCenterX(hang, plate)
    hang.head_hole.center.y == plate.bb.top - 8
}
