# Request (home): a rope-hung hallway shelf in 9 mm birch ply. Two boards 450 mm wide
# and 160 mm deep, hung 250 mm apart (board top to board top) on two loops of 10 mm rope
# that pass through four 12 mm holes in each board, hole centres 25 mm in from each end
# and 25 mm in from the front and back edges. The front edge of each board bows out
# 15 mm in a shallow arc (at the middle). Along the back of each board stands a gallery
# rail 450 long, 40 mm high above the board, glued in by three 40 mm through tenons into
# mortises whose back face is flush with the board's back edge. The upper rail carries
# "HOME SWEET HOME" engraved filled, bold sans, 16 mm capitals, centred on its face.

import "std/joints.aidl"

thickness 9 mm

board_w = 450 mm
board_d = 160 mm
bow = 15 mm
hole_d = 12 mm
hole_in = 25 mm
rail_h = 40 mm
tenon = 40 mm
tenons = 3
spacing = 250 mm
ply = 9 mm

# the arc of the bowed front: chord board_w, sagitta bow
bow_r = (square(board_w / 2) + square(bow)) / (2 * bow)

def board() -> solid {
    body = Rectangle(center=(0, 0), width=board_w, height=board_d)
    front_disc = Circle(center=(0, -board_d / 2 - bow + bow_r), radius=bow_r,
                        construction=true)
    front_band = Rectangle(center=(0, -board_d / 2 - bow / 2), width=board_w, height=bow,
                           construction=true)
    belly = Intersect(front_disc, front_band)
    hole rope {
        for i in range(2) {
            for j in range(2) {
                c = Circle(center=((i * 2 - 1) * (board_w / 2 - hole_in),
                                   (j * 2 - 1) * (board_d / 2 - hole_in)), diameter=hole_d)
            }
        }
    }
    # mortises: back face flush with the back edge, so centred ply/2 in from it
    mort = tab_and_slot(part="slot", length=board_w, thickness=ply, tabs=tenons, tab=tenon,
                        screw=0, cx=0 mm, cy=board_d / 2 - ply / 2)
}

def rail(label="") -> solid {
    # y = 0 is the tenons' tips (the board's underside); the rail shows rail_h above
    body = Rectangle(bottom_left=(-board_w / 2, 0), width=board_w, height=rail_h + ply)
    ten = tab_and_slot(part="tab", length=board_w, thickness=ply, tabs=tenons, tab=tenon,
                       screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    if label != "" {
        drawing words {
            t = Text(label, position=(0, ply + rail_h / 2), size=16, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
}

assembly rope_shelf {
    lower = board()
    upper = board()
    lower_rail = rail()
    upper_rail = rail(label="HOME SWEET HOME")

    # flat on the sheet: boards side by side, rails under them
    RightOf(upper, lower, gap=10)
    AlignTop(upper, lower)
    Below(lower_rail, lower, gap=10)
    AlignLeft(lower_rail, lower)
    Below(upper_rail, upper, gap=10)
    AlignLeft(upper_rail, upper)

    # in 3D: boards face up, rails stand on the back edges facing front
    Place(lower, position=(0, 0, 0), face="up")
    Place(upper, position=(0, 0, spacing), face="up")
    Place(lower_rail, position=(0, board_d / 2, 0), face="front", up="up")
    Place(upper_rail, position=(0, board_d / 2, spacing), face="front", up="up")

    # the request's numbers
    assert lower.body.bb.width == 450 mm, "board 450 wide"
    assert lower.body.bb.height == 160 mm, "board 160 deep"
    assert lower.bb.height - lower.body.bb.height == 15 mm, "front bows out 15"
    assert sum([len(r) for r in lower.rope.c]) == 4, "four rope holes per board"
    assert lower.rope.c[0][0].diameter == 12 mm, "12 mm rope holes"
    assert lower.rope.c[0][0].center.x - lower.body.bb.left == 25 mm, "holes 25 in from the end"
    assert lower.rope.c[0][0].center.y - lower.body.bb.bottom == 25 mm, "holes 25 in from the front"
    assert lower.body.bb.top - lower.rope.c[0][1].center.y == 25 mm, "holes 25 in from the back"
    assert len(lower.mort.slot) == 3, "three mortises"
    assert lower.body.bb.top - lower.mort.slot[0].bb.top == 0 mm, "mortise flush with the back"
    assert lower_rail.body.bb.height - ply == 40 mm, "rail 40 above the board"
    assert lower_rail.body.bb.width == 450 mm, "rail 450 long"
    assert upper_rail.words.t.size == 16 mm, "16 mm capitals"
    assert upper_rail.words.bb.width <= 450 mm - 20 mm, "words fit the rail"
}
