# An open tray with 3 x 4 compartments, 240 x 180 x 40 mm outside, 3 mm plywood.
import "std/boxes.aidl"

units mm
thickness 3 mm
kerf 0.15 mm

param length = 240 mm   # along x: 4 columns
param width = 180 mm    # along y: 3 rows
param height = 40 mm

assembly tray {
    t = divider_tray(length=length, width=width, height=height, rows=3, cols=4,
                     thickness=3 mm, finger=10 mm, clearance=0.3 mm, outside=true)
}
