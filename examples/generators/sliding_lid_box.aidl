# A pencil box whose lid slides out over its low front wall, in grooves of liners and rails.
# Outer size 80 x 200 x 45 mm (the lid slides along the 200 mm) from 3 mm plywood, 0.3 mm clearance.
#   aidl render sliding_lid_box.aidl --assembled -o box.png
import "std/boxes.aidl"

thickness 3 mm
kerf 0.15 mm

assembly kit {
    box = sliding_lid_box(length=80 mm, width=200 mm, height=45 mm, thickness=3 mm, clearance=0.3 mm)
}
