# Request (pets): a tool rack that hangs on the rim of a fish tank with 8 mm glass, cut from
# 6 mm acrylic. Two hook plates, 140 mm apart centre to centre, each an inverted U with a 9 mm
# gap over the glass (8 mm glass + 1 mm), legs 8 mm wide, the inner leg reaching 30 mm down
# inside the tank, the outer one 100 mm down outside; from the outer leg a bracket stands out
# 70 mm from the glass, its top 50 mm below the rim, braced by a sloping underside. On the two
# brackets a 150 x 62 mm shelf, glued on by two 15 mm tabs per bracket through mortises. In the
# shelf a row of five tool holders 27 mm apart: a 26 x 10 mm slot for the net handle, a
# 34 x 6 mm slot for the glass scraper, a 16 mm hole for the tongs, a 10 mm hole for the
# thermometer and an 8 mm hole for the feeding pipette; each named underneath, engraved 5 mm
# tall (at most 24 mm wide): NET, SCRAPER, TONGS, TEMP, FOOD.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
GLASS_GAP = 9 mm
LEG = 8 mm
REACH = 70 mm        # bracket's end from the glass
DROP = 50 mm         # bracket's top below the rim
SHELF_W = 150 mm
SHELF_D = REACH - LEG
HOOK_X = 70 mm       # each hook's middle from the shelf's centre
PITCH = 27 mm
NAMES = ["NET", "SCRAPER", "TONGS", "TEMP", "FOOD"]

# side view: x away from the glass (its outer face at x = 0), y up (the rim at y = 0)
def hook() -> solid {
    bridge = Rectangle(bottom_left=(-GLASS_GAP - LEG, 0), width=GLASS_GAP + 2 * LEG, height=LEG)
    inner = Rectangle(bottom_left=(-GLASS_GAP - LEG, -30), width=LEG, height=30 + LEG)
    outer = Rectangle(bottom_left=(0, -100), width=LEG, height=100 + LEG)
    arm = Polygon([(0, -95), (REACH, -DROP - 10 mm), (REACH, -DROP), (0, -DROP)])
    tabs = tab_and_slot(part="tab", length=SHELF_D, thickness=T, tabs=2, tab=15 mm, screw=0,
                        cx=LEG + SHELF_D / 2, cy=-DROP)
}

assembly aquarium_tool_rack {
    left_hook = hook()
    right_hook = hook()

    solid shelf {
        board = RoundedRectangle(center=(0, 0), width=SHELF_W, height=SHELF_D, corner_radius=4)
        seat_l = tab_and_slot(part="slot", length=SHELF_D, thickness=T, tabs=2, tab=15 mm,
                              screw=0, rotation=90 deg, cx=-HOOK_X, cy=0 mm)
        seat_r = tab_and_slot(part="slot", length=SHELF_D, thickness=T, tabs=2, tab=15 mm,
                              screw=0, rotation=90 deg, cx=HOOK_X, cy=0 mm)
        hole tools {
            net = Slot(center=(-2 * PITCH, 6), length=26, width=10, rotation=90)
            scraper = Slot(center=(-PITCH, 6), length=34, width=6, rotation=90)
            tongs = Circle(center=(0, 6), diameter=16)
            temp = Circle(center=(PITCH, 6), diameter=10)
            food = Circle(center=(2 * PITCH, 6), diameter=8)
        }
        drawing labels {
            for i in range(5) {
                t = Text(NAMES[i], position=((i - 2) * PITCH, -20), size=5, max_width=24,
                         valign="middle")
            }
        }
    }

    # on the sheet
    RightOf(right_hook, left_hook, gap=10)
    AlignBottom(right_hook, left_hook)
    Below(shelf, left_hook, gap=10)
    AlignLeft(shelf, left_hook)

    # in 3D: hook's x -> world y (away from the glass), y -> z, thickness -> x
    Place(left_hook, position=(-HOOK_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_hook, position=(HOOK_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(shelf, position=(0, LEG + SHELF_D / 2, -DROP - T))

    # the request's numbers
    assert left_hook.outer.bb.left - left_hook.inner.bb.right == 9 mm, "9 mm over the glass"
    assert left_hook.inner.height - LEG == 30 mm, "inner leg 30 down"
    assert left_hook.outer.height - LEG == 100 mm, "outer leg 100 down"
    assert shelf.board.width == 150 mm and shelf.board.height == 62 mm, "shelf 150 x 62"
    assert shelf.seat_r.slot[0].bb.center_x - shelf.seat_l.slot[0].bb.center_x == 140 mm,
        "hooks 140 apart"
    assert len(shelf.labels.t) == 5, "five tools"
    assert shelf.tools.temp.center.x - shelf.tools.tongs.center.x == 27 mm, "27 mm apart"
    assert shelf.tools.net.length == 26 mm and shelf.tools.net.width == 10 mm, "net slot"
    assert shelf.tools.scraper.length == 34 mm and shelf.tools.scraper.width == 6 mm, "scraper slot"
}
