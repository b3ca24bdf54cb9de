# Request: a soldering jig for an 8 x 8 x 8 LED cube of 5 mm LEDs, 3 mm ply.
# - Top plate 240 x 240 mm with an 8 x 8 grid of 5.1 mm LED holes at 25 mm pitch, centred.
# - Beside each hole an engraved bend mark (a 5 mm line, from 4 mm to 9 mm right of the
#   hole's centre) showing which way the cathode leg is bent.
# - Rows lettered A-H in the left margin, columns numbered 1-8 in the bottom margin, 5 mm
#   high; "LED CUBE 8x8x8  25 mm" engraved 6 mm high in the top margin.
# - The plate stands 60 mm up on two legs 220 mm long, crossed under the plate's centre
#   lines (between the holes) and halved into each other (30 + 30 mm), each glued into the
#   plate with 2 tabs 20 mm wide.
import "std/joints.aidl"

thickness 3 mm

t = 3 mm
plate_w = 240 mm
pitch = 25 mm
n = 8
led_d = 5.1 mm
leg_l = 220 mm
leg_h = 60 mm
grid0 = -(n - 1) / 2 * pitch          # first hole's centre, x and y
letters = ["A", "B", "C", "D", "E", "F", "G", "H"]

def leg(halving_from_top=false) -> solid {
    # the leg's bottom on y = 0, its shoulder at leg_h, the tabs' tips at leg_h + t
    body = Rectangle(bottom_left=(-leg_l / 2, 0), width=leg_l, height=leg_h + t)
    tabs = tab_and_slot(part="tab", length=leg_l, thickness=t, tabs=2, tab=20 mm, screw=0,
                        cx=0, cy=leg_h + t)
    if halving_from_top {
        # from the shoulder down to half height; it meets the middle gap between the tabs
        half = cross_halving(depth=leg_h / 2, thickness=t, cx=0, cy=leg_h)
        AllowOverlap(tabs, half)
    } else {
        half = cross_halving(depth=leg_h / 2, thickness=t, rotation=180 deg, cx=0, cy=0)
    }
}

assembly jig {
    solid plate {
        body = Rectangle(center=(0, 0), width=plate_w, height=plate_w)
        hole led {
            c = Circle(center=(grid0, grid0), diameter=led_d)
        }
        leds = GridPattern(led, n, n, pitch)
        slots_x = tab_and_slot(part="slot", length=leg_l, thickness=t, tabs=2, tab=20 mm,
                               screw=0, cx=0, cy=0)
        slots_y = tab_and_slot(part="slot", length=leg_l, thickness=t, tabs=2, tab=20 mm,
                               screw=0, rotation=90 deg, cx=0, cy=0)
        drawing marks {
            for r in range(n) {
                for c in range(n) {
                    m = Line((grid0 + c * pitch + 4 mm, grid0 + r * pitch),
                             (grid0 + c * pitch + 9 mm, grid0 + r * pitch))
                }
            }
            for r in range(n) {
                row_lab = Text(letters[r], position=(-plate_w / 2 + 12 mm, grid0 + r * pitch),
                               size=5, valign="middle")
            }
            for c in range(n) {
                col_lab = Text(str(c + 1), position=(grid0 + c * pitch, -plate_w / 2 + 12 mm),
                               size=5, valign="middle")
            }
            title = Text("LED CUBE 8x8x8  25 mm", position=(0, plate_w / 2 - 12 mm), size=6,
                         valign="middle")
        }
    }

    leg_x = leg(halving_from_top=false)     # runs along x under the plate's y = 0 line
    leg_y = leg(halving_from_top=true)      # runs along y under the plate's x = 0 line

    Below(leg_x, plate, gap=10)
    AlignLeft(leg_x, plate)
    Below(leg_y, leg_x, gap=10)
    AlignLeft(leg_y, leg_x)

    # 3D: legs stand on z = 0, the plate on their shoulders
    Place(plate, position=(0, 0, leg_h), face="up")
    Place(leg_x, position=(0, t / 2, 0), face="front", up="up")
    Place(leg_y, position=(-t / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert plate.body.width == 240 mm and plate.body.height == 240 mm, "plate 240 x 240"
    assert len(plate.leds) == 64, "8 x 8 LED holes"
    assert plate.leds[1].c.center.x - plate.leds[0].c.center.x == 25 mm, "25 mm pitch across"
    assert plate.leds[8].c.center.y - plate.leds[0].c.center.y == 25 mm, "25 mm pitch up"
    assert plate.leds[0].c.diameter == 5.1 mm, "5.1 mm holes"
    assert plate.leds[0].c.center.x + plate.leds[63].c.center.x == 0 mm, "grid centred"
    assert leg_x.body.width == 220 mm, "legs 220 mm long"
    assert leg_x.half.cut.bb.height + leg_y.half.cut.bb.height == 60 mm, "halvings 30 + 30"
}
