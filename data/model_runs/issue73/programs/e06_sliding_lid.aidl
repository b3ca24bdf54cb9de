# A box with a sliding lid.
import "std/boxes.aidl"
assembly kit {
    box = sliding_lid_box(length=100 mm, width=70 mm, height=40 mm, thickness=3 mm)
}
