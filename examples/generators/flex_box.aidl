# A rounded box whose wall bends round the corners on living hinges.
import "std/boxes.aidl"
thickness 3 mm
kerf 0.15 mm

assembly round_box {
    box = flex_box(length=120 mm, width=80 mm, height=50 mm, radius=20 mm, thickness=3 mm)
}
