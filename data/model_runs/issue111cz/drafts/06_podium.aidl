# Request (sport): a table-top winners' podium for the family games-night trophies, 3 mm ply,
# glued. Three steps side by side, each 100 mm wide and 80 mm deep: 2nd place on the left 60 mm
# tall, 1st in the middle 90 mm tall, 3rd on the right 40 mm tall (heights to the top surface).
# Built from 5 parts: a stepped front and a stepped back (standing 5 mm in from the tops' front
# and back edges) and three 100 x 80 tops, each glued onto two tabs per step of the front and the
# back (tabs through closed slots in the tops, flush with the top surface). The front has the
# place numbers cut right through in a bold font, centred on each step's face: "1" 40 mm tall,
# "2" 30 mm, "3" 20 mm; a five-pointed star (12 mm outer, 5 mm inner radius) engraved centred
# above the "1", 10 mm below the top of its step.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
STEP_W = 100 mm
DEPTH = 80 mm
INSET = 5 mm                      # front and back stand this far in from the tops' edges
HEIGHTS = [60 mm, 90 mm, 40 mm]   # left (2nd), middle (1st), right (3rd)
PLACES = ["2", "1", "3"]
NUM_SIZE = [30 mm, 40 mm, 20 mm]
XS = [-STEP_W, 0 mm, STEP_W]      # the steps' centres
# FIX after the first valid program: the "1" (40 tall, centred on its 87 mm face) ran into the
# star (W0505); the "1" is now centred in the face below the star, 5 mm clear of it
STAR_Y = HEIGHTS[1] - T - 10 mm - 12 mm
STAR_BOTTOM = STAR_Y - 12 mm * cos(36 deg)
NUM_Y = [(HEIGHTS[0] - T) / 2, (STAR_BOTTOM - 5 mm) / 2, (HEIGHTS[2] - T) / 2]
WALL_Y = DEPTH / 2 - INSET - T / 2   # the front's and back's middle from the tops' centre line

def stepped(numbers=false) -> solid {
    body = Polygon([(-1.5 * STEP_W, 0), (1.5 * STEP_W, 0), (1.5 * STEP_W, HEIGHTS[2]),
                    (0.5 * STEP_W, HEIGHTS[2]), (0.5 * STEP_W, HEIGHTS[1]),
                    (-0.5 * STEP_W, HEIGHTS[1]), (-0.5 * STEP_W, HEIGHTS[0]),
                    (-1.5 * STEP_W, HEIGHTS[0])])
    for j in range(3) {
        tabs = tab_and_slot(part="tab", length=STEP_W, thickness=T, tabs=2, tab=20 mm, screw=0,
                            cx=XS[j], cy=HEIGHTS[j])
    }
    if numbers {
        for j in range(3) {
            hole num {
                t = Text(PLACES[j], position=(XS[j], NUM_Y[j]), size=NUM_SIZE[j],
                         font="sans:Bold", valign="middle")
            }
        }
        drawing star {
            s = Star(center=(0, STAR_Y), points=5, outer_radius=12 mm,
                     inner_radius=5 mm)
        }
    }
}

def step_top() -> solid {
    body = Rectangle(center=(0, 0), width=STEP_W, height=DEPTH)
    front_slots = tab_and_slot(part="slot", length=STEP_W, thickness=T, tabs=2, tab=20 mm,
                               screw=0, cx=0, cy=-WALL_Y)
    back_slots = tab_and_slot(part="slot", length=STEP_W, thickness=T, tabs=2, tab=20 mm,
                              screw=0, cx=0, cy=WALL_Y)
}

assembly podium {
    front = stepped(numbers=true)
    back = stepped(numbers=false)
    for j in range(3) {
        top = step_top()
    }

    # on the sheet: the back above the front, the tops above the back in a row
    Above(back, front, gap=5 mm)
    Above(top[1], back, gap=5 mm)
    AlignCenterX(top[1], back)
    LeftOf(top[0], top[1], gap=5 mm)
    RightOf(top[2], top[1], gap=5 mm)
    AlignBottom(top[0], top[1])
    AlignBottom(top[2], top[1])

    # in 3D: x across, the front toward -y; both stepped panels read from the front
    Place(front, position=(0, -WALL_Y + T / 2, 0), face="front", up="up")
    Place(back, position=(0, WALL_Y + T / 2, 0), face="front", up="up")
    for j in range(3) {
        Place(top[j], position=(XS[j], 0, HEIGHTS[j] - T), face="up")
    }

    assert front.body.bb.width == 300 mm, "three steps of 100"
    assert top[0].body.bb.height == 80 mm, "80 deep"
    assert HEIGHTS[1] == 90 mm and HEIGHTS[0] == 60 mm and HEIGHTS[2] == 40 mm, "90 / 60 / 40 tall"
    assert front.num[1].t.size == 40 mm and front.num[0].t.size == 30 mm and front.num[2].t.size == 20 mm,
        "numbers 40 / 30 / 20"
    assert HEIGHTS[1] - T - front.star.s.bb.top == 10 mm, "star 10 below the top"
}
