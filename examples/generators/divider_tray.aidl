# A parts tray of 3 x 4 equal compartments whose dividers cross in halving slots.
# Outer size 160 x 110 x 40 mm from 3 mm plywood.
#   aidl render divider_tray.aidl --assembled -o tray.png
import "std/boxes.aidl"

thickness 3 mm
kerf 0.15 mm

assembly kit {
    tray = divider_tray(length=160 mm, width=110 mm, height=40 mm, rows=3, cols=4, thickness=3 mm)
}
