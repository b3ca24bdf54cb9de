# A finger-jointed box with a lift-off lid: the lid's lip fits inside the walls.
# Inside size 100 x 60 x 40 mm from 3 mm plywood, 0.3 mm clearance for the lip.
#   aidl render lid_box.aidl --assembled -o box.png
import "std/boxes.aidl"

thickness 3 mm
kerf 0.15 mm

assembly kit {
    box = lid_box(length=100 mm, width=60 mm, height=40 mm, thickness=3 mm, clearance=0.3 mm, outside=false)
}
