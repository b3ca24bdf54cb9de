# Request (workshop): a sandpaper tearing jig for 230 x 280 mm sheets, cut from 6 mm ply.
# Base 320 x 280 mm with R8 corners and an 8 mm hanging hole centred 12 mm below the top edge.
# A tear bar 40 x 280 mm (R4 corners) is clamped across the base by two M6 carriage bolts
# (wing nuts), its left edge -- the tearing edge -- 220 mm from the base's left edge; bolt
# holes 12 mm from the bar's ends, the same holes in the base. A stop, 240 mm long standing
# 12 mm above the base, plugs by two 30 mm tabs into one of three mortise pairs, so that its
# face is 140 mm (1/2), 93.3 mm (1/3) or 70 mm (1/4) from the tearing edge: the sheet's end
# goes against the stop, the bar clamps it, the free piece is torn up against the bar's edge.
# Engraved: "1/2", "1/3", "1/4" by each mortise pair, a line marking the tearing edge, and
# "SANDPAPER 230 x 280" in the bottom margin; "LIFT AND TEAR" on the bar.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

t = 6 mm
base_w = 320 mm
base_h = 280 mm
tear_x = -base_w / 2 + 220 mm      # tearing edge, in the base's frame (centre at 0, 0)
bar_w = 40 mm
bolt_y = base_h / 2 - 12 mm
stop_len = 240 mm
pieces = [140 mm, 280 mm / 3, 70 mm]
names = ["1/2", "1/3", "1/4"]

def mortise_x(p) = tear_x - p - t / 2

assembly tearer {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=base_w, height=base_h, corner_radius=8)
        hole hang { c = Circle(center=(0, base_h / 2 - 12 mm), diameter=8) }
        b1 = clearance_hole(size=6, cx=tear_x + bar_w / 2, cy=bolt_y)
        b2 = clearance_hole(size=6, cx=tear_x + bar_w / 2, cy=-bolt_y)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=stop_len, thickness=t, tabs=2, tab=30 mm,
                             screw=0, rotation=90 deg, cx=mortise_x(pieces[i]), cy=0)
        }
        drawing marks {
            edge = Line((tear_x, -base_h / 2 + 20 mm), (tear_x, base_h / 2 - 20 mm))
            for i in range(3) {
                lab = Text(names[i], position=(mortise_x(pieces[i]), 0), size=7,
                           valign="middle", rotation=90 deg)
            }
            title = Text("SANDPAPER 230 x 280", position=(-40 mm, -base_h / 2 + 10 mm), size=6,
                         valign="middle")
        }
        Fixed(body)
        assert abs(tear_x - (base.body.bb.left + 220 mm)) < 0.01 mm, "tearing edge 220 mm in"
        assert abs((tear_x - (m[0].slot[0].bb.center_x + t / 2)) - 140 mm) < 0.1 mm, "half"
        assert abs((tear_x - (m[1].slot[0].bb.center_x + t / 2)) - 93.3 mm) < 0.1 mm, "third"
        assert abs((tear_x - (m[2].slot[0].bb.center_x + t / 2)) - 70 mm) < 0.1 mm, "quarter"
        assert base.body.bb.top - hang.c.center.y == 12 mm
    }

    solid bar {
        body = RoundedRectangle(center=(tear_x + bar_w / 2, 0), width=bar_w, height=base_h,
                                corner_radius=4)
        h1 = clearance_hole(size=6, cx=tear_x + bar_w / 2, cy=bolt_y)
        h2 = clearance_hole(size=6, cx=tear_x + bar_w / 2, cy=-bolt_y)
        drawing word {
            w = Text("LIFT AND TEAR", position=(tear_x + bar_w / 2, 0), size=8,
                     valign="middle", rotation=90 deg)
        }
        Fixed(body)
        Fixed(h1)
        Fixed(h2)
        assert bar.body.bb.top - h1.c.center.y == 12 mm
    }

    solid stop {
        body = Rectangle(center=(0, 0), width=stop_len, height=12 mm + t)
        tabs = tab_and_slot(part="tab", length=stop_len, thickness=t, tabs=2, tab=30 mm,
                            screw=0, rotation=180 deg, cx=0, cy=-(12 mm + t) / 2)
        Fixed(body)
    }

    # on the sheet: bar and stop beside the base
    RightOf(bar, base, gap=8)
    AlignTop(bar, base)
    Below(stop, base, gap=8)
    AlignLeft(stop, base)

    # assembled: the bar over the tearing edge, the stop in the half-sheet mortises
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(bar, position=(0, 0, t), face="up", up="back")
    Place(stop, position=(mortise_x(pieces[0]) - t / 2, 0, (12 mm + t) / 2 + 0 mm),
          face="right", up="up")
}
