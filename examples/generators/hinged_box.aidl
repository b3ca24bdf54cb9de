# A box with a lid on a pin hinge, the pins cut from the same sheet.
import "std/boxes.aidl"
thickness 3 mm
kerf 0.15 mm

assembly keepsake {
    box = hinged_box(length=140 mm, width=90 mm, height=60 mm, thickness=3 mm, clearance=0.3 mm)
}
