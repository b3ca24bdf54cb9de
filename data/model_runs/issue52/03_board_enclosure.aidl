# An enclosure for the 64 x 42 mm board in board.dxf (layer Edge.Cuts),
# 3 mm acrylic, with a USB opening in one short side (the left, x = 0 edge).
import "std/enclosures.aidl"

units mm
thickness 3 mm
kerf 0.15 mm

param board_w = 64 mm     # board outline along x (from board.dxf)
param board_h = 42 mm     # board outline along y
param usb_w = 12 mm       # USB connector opening, with margin
param usb_h = 7 mm
param usb_y = 21 mm       # opening's centre along the left edge, board coordinates

assembly enclosure {
    box = board_enclosure(width=board_w, height=board_h, depth=25 mm, thickness=3 mm,
                          clearance=2 mm,
                          holes=[[3.5, 3.5], [60.5, 3.5], [60.5, 38.5], [3.5, 38.5]],
                          hole_d=3.2 mm, standoff=5 mm,
                          ports=[["left", usb_y, usb_w, usb_h]],
                          vent="slots", finger=10 mm)
}
