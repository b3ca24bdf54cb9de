# Request (music): a 1D quadratic-residue acoustic diffuser for a home studio wall, 3 mm ply.
# N = 7 wells, each 40 mm wide, 300 mm long, separated by 8 fins 3 mm thick (outside width
# 7 x 40 + 8 x 3 = 304 mm). Well depths follow n^2 mod 7 = 0, 1, 4, 2, 2, 4, 1 times 25 mm
# (deepest 100 mm, design frequency about 1 kHz); every well also sits 6 mm behind the fins'
# front edge, so the fins stand 106 mm off the back. The fins stand on a 304 x 300 back on
# three 30 mm tenons each. Each well bottom is a 40 x 300 plate (the 100 mm wells use the
# back) with two 40 mm tabs into each neighbouring fin, the left tabs at -100 and +50 mm and
# the right at -50 and +100 mm along the well so that two plates at one depth never meet in
# one mortise. Plates are engraved with their well number and depth, fins with their number.
# Two keyholes (8 mm head, 10 mm slot up) in the back inside the two deepest wells, 100 mm
# above the middle, to hang it.

units mm
thickness 3 mm

import "std/joints.aidl"
import "std/plates.aidl"

T = 3 mm
N = 7
well_w = 40 mm
length = 300 mm
depth_unit = 25 mm
lip = 6 mm
q = [(n * n) % N for n in range(N)]
depths = [v * depth_unit for v in q]
fin_d = lip + 4 * depth_unit            # fins stand this far off the back
width = N * well_w + (N + 1) * T
left_tabs = [-100, 50]
right_tabs = [-50, 100]
plate_wells = [k for k in range(N) if depths[k] < 4 * depth_unit]

def fin_x(i) = -width / 2 + i * (well_w + T)            # a fin's left face
def well_x(k) = fin_x(k) + T + well_w / 2                # a well's centre
def mortise_y(d) = T + fin_d - lip - d - T / 2           # in a fin: the plate's mid-plane

def fin(dl=100 mm, dr=100 mm, name="F0") -> solid {
    body = Rectangle(bottom_left=(-length / 2, 0), width=length, height=T + fin_d)
    tenons = tab_and_slot(part="tab", length=length, thickness=T, tabs=3, tab=30 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=0 mm)
    if dl < 100 mm {
        hole from_left {
            for y in right_tabs {
                m = Rectangle(center=(y * 1 mm, mortise_y(dl)), width=40, height=T)
            }
        }
    }
    if dr < 100 mm {
        hole from_right {
            for y in left_tabs {
                m = Rectangle(center=(y * 1 mm, mortise_y(dr)), width=40, height=T)
            }
        }
    }
    drawing mark { t = Text(name, position=(-138, 90), size=5, valign="middle") }
}

def well_plate(name="W0") -> solid {
    core = Rectangle(center=(0, 0), width=well_w, height=length)
    for y in left_tabs {
        lt = Rectangle(center=(-well_w / 2 - T / 2, y * 1 mm), width=T, height=40)
    }
    for y in right_tabs {
        rt = Rectangle(center=(well_w / 2 + T / 2, y * 1 mm), width=T, height=40)
    }
    drawing mark { t = Text(name, position=(0, 135), size=5, valign="middle") }
}

assembly diffuser {
    solid back {
        # FIX after the first valid program: the outer fins stood on the back's very edge, so
        # their mortises were open notches (W0530): the back is 8 mm wider each side (320)
        body = Rectangle(center=(0, 0), width=width + 16 mm, height=length)
        for i in range(N + 1) {
            m = tab_and_slot(part="slot", length=length, thickness=T, tabs=3, tab=30 mm, screw=0,
                             rotation=90 deg, cx=fin_x(i) + T / 2, cy=0 mm)
        }
        hang_a = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=well_x(2), cy=100 mm)
        hang_b = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=well_x(5), cy=100 mm)
    }

    for i in range(N + 1) {
        f = fin(dl=(depths[i - 1] if i > 0 else 100 mm), dr=(depths[i] if i < N else 100 mm),
                name=f"F{i}")
        Place(f, position=(fin_x(i), 0, 0), face="right", up="up")
    }
    for k in plate_wells {
        p = well_plate(name=f"W{k} {depths[k] / 1 mm:.0f}")
        Place(p, position=(well_x(k), 0, T + fin_d - lip - depths[k] - T))
    }
    Place(back, position=(0, 0, 0))

    # flat on the sheet
    Below(f[0], back, gap=10)
    AlignLeft(f[0], back)
    for i in range(1, N + 1) {
        Below(f[i], f[i - 1], gap=5)
        AlignLeft(f[i], f[i - 1])
    }
    RightOf(p[0], back, gap=10)
    AlignTop(p[0], back)
    for j in range(1, len(plate_wells)) {
        RightOf(p[j], p[j - 1], gap=5)
        AlignTop(p[j], p[j - 1])
    }

    # the request's numbers
    assert q == [0, 1, 4, 2, 2, 4, 1], "n^2 mod 7"
    assert depths[2] == 100 mm and depths[1] == 25 mm, "25 mm per step, deepest 100"
    assert back.body.bb.width == 320 mm and back.body.bb.height == 300 mm, "back 320 x 300 (fix)"
    assert len(f) == 8 and len(p) == 5, "8 fins, 5 well plates"
    assert fin_x(1) - (fin_x(0) + T) == 40 mm, "wells 40 wide"
    assert f[0].body.bb.height - 3 mm == 106 mm, "fins stand 106 off the back"
    assert p[0].core.bb.width == 40 mm and p[0].core.bb.height == 300 mm, "plates 40 x 300"
    assert back.hang_a.head_hole.center.y - back.body.bb.center_y == 100 mm, "keyholes 100 above the middle"
}
