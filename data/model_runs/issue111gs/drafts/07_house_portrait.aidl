# Request: a new-home present for the Patels, a layered portrait of their house in
# 3 mm ply (four pieces glued in three layers).
# - Back: 200 x 170 mm, R8 corners; two keyholes to hang it (8 mm head, 4 mm slot,
#   10 mm long, pointing up) at x = -80 and +80 mm, 60 mm above the middle;
#   "THE PATELS · 2026" engraved in filled letters 8 mm tall, centred 72 mm below
#   the middle.
# - House (second layer): walls 120 mm wide x 86 mm tall, their bottom 55 mm below the
#   middle; three upper windows 18 x 22 mm at x = -36, 0, +36 (centres 8 mm above the
#   middle), two lower windows 18 x 22 at x = -36 and +36 (centres 33 mm below), all cut
#   through so the back shows; a door opening 24 mm wide with a round top, its sill
#   4 mm above the walls' bottom, 38 mm tall.
# - Roof (front layer): a gable 140 mm wide and 48 mm tall whose lower edge lies 6 mm
#   over the top of the walls, with a chimney 12 x 22 mm centred at x = +35, 10 mm
#   poking above the slope; tile lines engraved every 6 mm, kept 4 mm in from the
#   slopes and 3 mm clear of the chimney.
# - Door (second layer, in the opening): 0.3 mm smaller all round than the opening,
#   "42" engraved in filled letters 7 mm tall, a 3 mm filled knob.

units mm
thickness 3 mm
import "std/plates.aidl"

def hw(y) = 70 * (73 - y) / 48          # the roof's half width at height y
def ty(j) = 31 + 6 * j                   # the j-th tile line's height
def tile_r(j) = min(hw(ty(j)) - 4, 26) if ty(j) > 34 else hw(ty(j)) - 4

assembly portrait {
    solid back {
        board = RoundedRectangle(center=(0, 0), width=200, height=170, corner_radius=8)
        hang_l = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=-80, cy=60)
        hang_r = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=80, cy=60)
        drawing name {
            t = Text("THE PATELS · 2026", position=(0, -72), size=8, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    solid house {
        walls = Rectangle(center=(0, -12), width=120, height=86)
        hole upper {
            w = Rectangle(center=(-36, 8), width=18, height=22)
        }
        row = LinearPattern(upper, 3, (36, 0))
        hole lower {
            a = Rectangle(center=(-36, -33), width=18, height=22)
            b = Rectangle(center=(36, -33), width=18, height=22)
        }
        hole door_way {
            r = Rectangle(center=(0, -38), width=24, height=26)
            c = Circle(center=(0, -25), radius=12)
        }
    }

    solid roof {
        gable = Triangle(center=(0, 49), base=140, height=48)
        chimney = Rectangle(center=(35, 48), width=12, height=22)
        drawing tiles {
            for j in range(7) {
                l = Line((4 - hw(ty(j)), ty(j)), (tile_r(j), ty(j)))
            }
        }
    }

    solid door {
        slab = Rectangle(center=(0, -37.85), width=23.4, height=25.7)
        top = Circle(center=(0, -25), radius=11.7)
        drawing marks {
            n = Text("42", position=(0, -30), size=7, font="sans:Bold", valign="middle",
                     fill=true)
            knob = Circle(center=(8, -44), diameter=3, fill=true)
        }
    }

    # flat on the sheet
    RightOf(house, back, gap=10)
    AlignTop(house, back)
    Below(roof, house, gap=10)
    AlignLeft(roof, house)
    RightOf(door, roof, gap=10)
    AlignTop(door, roof)

    # assembled: lying face up, stacked
    Place(back, position=(0, 0, 0), face="up")
    Place(house, position=(0, 0, 3), face="up")
    Place(door, position=(0, 0, 3), face="up")
    Place(roof, position=(0, 0, 6), face="up")

    # the request's numbers
    assert back.board.width == 200 mm and back.board.height == 170 mm, "back 200 x 170"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 160 mm,
        "keyholes at -80 / +80"
    assert back.hang_l.head_hole.center.y - back.board.center.y == 60 mm, "keyholes 60 up"
    assert back.name.t.size == 8 mm, "name 8 mm"
    assert house.walls.width == 120 mm and house.walls.height == 86 mm, "walls 120 x 86"
    assert back.board.center.y - house.walls.bb.bottom == 55 mm, "walls' bottom 55 below"
    assert len(house.row) == 3, "three upper windows"
    assert house.row[2].w.center.x - house.row[0].w.center.x == 72 mm, "windows at -36 / 0 / +36"
    assert house.row[0].w.width == 18 mm and house.row[0].w.height == 22 mm, "windows 18 x 22"
    assert house.door_way.r.width == 24 mm, "door opening 24 wide"
    assert house.door_way.bb.bottom - house.walls.bb.bottom == 4 mm, "sill 4 mm up"
    assert house.door_way.bb.height == 38 mm, "door opening 38 tall"
    assert roof.gable.base == 140 mm and roof.gable.height == 48 mm, "roof 140 x 48"
    assert house.walls.bb.top - roof.gable.bb.bottom == 6 mm, "roof 6 mm over the walls"
    assert house.row[0].bb.top + 3 mm <= roof.gable.bb.bottom, "windows clear of the roof"
    assert roof.chimney.bb.top - (roof.gable.bb.bottom + 48 mm * (1 - 35 / 70)) == 10 mm,
        "chimney 10 above the slope"
    assert house.door_way.r.width - door.slab.width == 0.6 mm, "door 0.3 smaller all round"
    assert back.name.bb.top + 3 mm <= house.walls.bb.bottom, "name clear of the house"
}
