# Request (home): a hallway key rack in 6 mm ply. A 200 x 70 mm back plate with R8 corners,
# hung on two screws by keyholes 160 mm apart, 15 mm below the top edge. Four hook pegs
# (12 mm wide, 40 mm long, a 20 mm round knob at the end) stand out of the plate, each glued
# by one 8 mm tenon into a mortise in the plate, the mortises 40 mm apart in a row 15 mm above
# the bottom edge. "KEYS" engraved in bold 14 mm letters in the middle of the plate.
units mm
thickness 6 mm
import "std/joints.aidl"
import "std/plates.aidl"

param plate_w = 200 mm, min = 160, max = 300
param plate_h = 70 mm, min = 60, max = 100
param pegs = 4, min = 2, max = 6
param pitch = 40 mm, min = 30, max = 50

def peg() -> solid {
    stem = Rectangle(center=(0, 20), width=12, height=40)
    knob = Circle(center=(0, 40), diameter=20)
    t = tab_and_slot(part="tab", length=12 mm, thickness=6 mm, tabs=1, tab=8 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly key_rack {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
        k1 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=-80 mm, cy=plate_h / 2 - 15 mm)
        k2 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=80 mm, cy=plate_h / 2 - 15 mm)
        for i in range(pegs) {
            m = tab_and_slot(part="slot", length=12 mm, thickness=6 mm, tabs=1, tab=8 mm,
                             screw=0, cx=(i - (pegs - 1) / 2) * pitch, cy=-plate_h / 2 + 15 mm)
        }
        drawing label {
            word = Text("KEYS", (0, 0), size=14, font="sans:Bold", valign="middle")
        }
        AlignCenterX(label, body)
        assert k2.head_hole.center.x - k1.head_hole.center.x == 160 mm, "keyholes 160 apart"
        assert body.bb.top - k1.head_hole.center.y == 15 mm, "keyholes 15 below top"
        assert len(m) == 4, "four mortises"
        assert m[1].slot[0].bb.center_x - m[0].slot[0].bb.center_x == 40 mm, "mortises 40 apart"
    }
    for j in range(pegs) {
        p = peg()
    }
    for j in range(pegs) {
        Below(p[j], plate, gap=10 + j * 0)
        p[j].bb.center_x == plate.bb.left + 30 + j * 45
    }
    assert plate.body.bb.width == 200 mm and plate.body.bb.height == 70 mm, "plate size"
    assert p[0].stem.bb.height == 40 mm and p[0].stem.bb.width == 12 mm, "peg size"
}
