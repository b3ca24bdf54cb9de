# Request (toys): a two-player battleship game in 3 mm ply, played with 3 mm pegs 15 mm long
# in 3.2 mm holes. Base 260 x 300 mm. Each player has, on their own half of the base, an
# "ocean" grid of 10 x 10 holes at 10 mm pitch with letters A-J over the columns and numbers
# 1-10 beside the rows, and a fleet tracker beside it: five ships of 5, 4, 3, 3 and 2 holes
# (10 mm pitch), each ringed by an engraved 8 mm wide outline with its length under it.
# Player B's half is player A's turned 180 degrees so both read it the right way up. Two
# screens 260 wide stand 140 mm above the base, 30 mm apart (centred), each on two 30 mm
# tenons through the base; each carries the player's "target" grid (10 x 10, same pitch,
# labelled the same) centred across it, facing that player, and the word TARGET.

units mm
thickness 3 mm

import "std/joints.aidl"

T = 3 mm
pitch = 10 mm
peg_d = 3.2 mm
cols = ["A", "B", "C", "D", "E", "F", "G", "H", "I", "J"]
ships = [5, 4, 3, 3, 2]
gap = 30 mm
screen_h = 140 mm

def field(x0=0 mm, y0=0 mm, s=1) -> hole {
    for r in range(10) {
        for c in range(10) {
            h = Circle(center=(s * (x0 + c * pitch), s * (y0 - r * pitch)), diameter=peg_d)
        }
    }
}

def field_labels(x0=0 mm, y0=0 mm, s=1) -> drawing {
    for c in range(10) {
        letter = Text(cols[c], position=(s * (x0 + c * pitch), s * (y0 + 9 mm)), size=4,
                      valign="middle", rotation=90 deg * (1 - s))
    }
    for r in range(10) {
        number = Text(str(r + 1), position=(s * (x0 - 9 mm), s * (y0 - r * pitch)), size=4,
                      valign="middle", rotation=90 deg * (1 - s))
    }
}

def fleet(s=1) -> hole {
    for k in range(5) {
        for j in range(ships[k]) {
            p = Circle(center=(s * (20 mm + k * 20 mm), s * (-40 mm - j * pitch)), diameter=peg_d)
        }
    }
}

def fleet_marks(s=1) -> drawing {
    for k in range(5) {
        ring = Slot(start=(s * (20 mm + k * 20 mm), s * -40 mm),
                    end=(s * (20 mm + k * 20 mm), s * (-40 mm - (ships[k] - 1) * pitch)), width=8)
        n = Text(str(ships[k]), position=(s * (20 mm + k * 20 mm), s * (-40 mm - ships[k] * pitch)),
                 size=4, valign="middle", rotation=90 deg * (1 - s))
    }
}

def screen() -> solid {
    body = Rectangle(bottom_left=(-130, 0), width=260, height=screen_h + T)
    tenons = tab_and_slot(part="tab", length=260 mm, thickness=T, tabs=2, tab=30 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=0 mm)
    target = field(x0=-45 mm, y0=128 mm)
    drawing marks {
        labels = field_labels(x0=-45 mm, y0=128 mm)
        word = Text("TARGET", position=(88, 80), size=8, font="sans:Bold", valign="middle",
                    fill=true)
    }
}

assembly battleship {
    solid base {
        body = Rectangle(center=(0, 0), width=260, height=300)
        mort_a = tab_and_slot(part="slot", length=260 mm, thickness=T, tabs=2, tab=30 mm, screw=0,
                              cx=0 mm, cy=-gap / 2 - T / 2)
        mort_b = tab_and_slot(part="slot", length=260 mm, thickness=T, tabs=2, tab=30 mm, screw=0,
                              cx=0 mm, cy=gap / 2 + T / 2)
        ocean_a = field(x0=-100 mm, y0=-40 mm, s=1)
        ocean_b = field(x0=-100 mm, y0=-40 mm, s=-1)
        fleet_a = fleet(s=1)
        fleet_b = fleet(s=-1)
        drawing marks {
            labels_a = field_labels(x0=-100 mm, y0=-40 mm, s=1)
            labels_b = field_labels(x0=-100 mm, y0=-40 mm, s=-1)
            ships_a = fleet_marks(s=1)
            ships_b = fleet_marks(s=-1)
        }
    }
    screen_a = screen()
    screen_b = screen()

    # flat on the sheet
    RightOf(screen_a, base, gap=10)
    AlignTop(screen_a, base)
    Below(screen_b, screen_a, gap=10)
    AlignLeft(screen_b, screen_a)

    # assembled: A sits at -y, B at +y
    Place(base, position=(0, 0, 0))
    Place(screen_a, position=(0, -gap / 2, 0), face="front", up="up")
    Place(screen_b, position=(0, gap / 2, 0), face="back", up="up")

    # the request's numbers
    assert base.body.bb.width == 260 mm and base.body.bb.height == 300 mm, "base 260 x 300"
    assert len(base.ocean_a.h) == 10 and len(base.ocean_a.h[0]) == 10, "10 x 10 ocean"
    assert len(screen_a.target.h) == 10 and len(screen_a.target.h[9]) == 10, "10 x 10 target"
    assert base.ocean_a.h[0][1].center.x - base.ocean_a.h[0][0].center.x == 10 mm, "10 mm pitch"
    assert base.ocean_a.h[0][0].diameter == 3.2 mm, "3.2 mm peg holes"
    assert len(base.fleet_a.p) == 5 and len(base.fleet_a.p[0]) == 5 and len(base.fleet_a.p[4]) == 2,
        "ships of 5 ... 2"
    assert (base.mort_b.slot[0].bb.center_y - base.mort_a.slot[0].bb.center_y) - 3 mm == 30 mm,
        "screens 30 apart"
    assert screen_a.body.bb.height - 3 mm == 140 mm, "screens 140 above the base"
    assert screen_a.body.bb.width == 260 mm, "screens 260 wide"
    assert (15 mm - 3 mm) < 30 mm / 2, "a 15 mm peg through a screen stops short of the middle"
    assert screen_a.target.h[0][0].center.x + screen_a.target.h[0][9].center.x == 0 mm,
        "target grid centred across the screen"
}
