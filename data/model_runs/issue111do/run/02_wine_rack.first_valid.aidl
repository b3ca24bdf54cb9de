# Request: a countertop wine rack for 4 bottles lying side by side, cut from 6 mm ply.
# Bottles are 80 mm across the body with a 30 mm neck. Two boards 400 mm long carry the
# bottles: the back board has 4 round cradles of 82 mm for the bodies, 25 mm deep; the front
# board has 4 cradles of 32 mm for the necks, 12 mm deep; the bottles' axis 95 mm above the
# counter, 95 mm apart. The boards stand 170 mm apart on two arched legs 240 mm long and
# 50 mm tall, joined by cross halvings (0.2 mm clearance) 170 mm apart at x = +-170 mm.
# "SALUTE" engraved filled across the front board.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
axis_h = 95 mm          # bottles' axis above the counter
pitch = 95 mm           # between bottles
n_bottles = 4
board_len = 400 mm
leg_len = 240 mm
leg_h = 50 mm
leg_x = 170 mm          # legs' planes from the middle
board_gap = 170 mm      # between the two boards' middles
halve = 25 mm           # each half of a cross halving

def cradle_board(cradle_r=41 mm, dip=25 mm) -> solid {
    body = Rectangle(bottom_left=(-board_len / 2, 0), width=board_len,
                     height=axis_h - cradle_r + dip)
    hole cradles {
        for i in range(n_bottles) {
            c = Circle(center=((i - (n_bottles - 1) / 2) * pitch, axis_h), radius=cradle_r)
        }
    }
    left_joint = cross_halving(depth=halve, thickness=T, clearance=0.2 mm, rotation=180 deg,
                               cx=-leg_x, cy=0 mm)
    right_joint = cross_halving(depth=halve, thickness=T, clearance=0.2 mm, rotation=180 deg,
                                cx=leg_x, cy=0 mm)
}

def leg() -> solid {
    top = Line((-leg_len / 2, leg_h), (leg_len / 2, leg_h))
    right = Line((leg_len / 2, leg_h), (leg_len / 2, 0))
    right_foot = Line((leg_len / 2, 0), (95, 0))
    arch = Arc(start=(95, 0), through=(0, 20), end=(-95, 0))
    left_foot = Line((-95, 0), (-leg_len / 2, 0))
    left = Line((-leg_len / 2, 0), (-leg_len / 2, leg_h))
    front_joint = cross_halving(depth=leg_h - halve, thickness=T, clearance=0.2 mm,
                                cx=-board_gap / 2, cy=leg_h)
    back_joint = cross_halving(depth=leg_h - halve, thickness=T, clearance=0.2 mm,
                               cx=board_gap / 2, cy=leg_h)
    Rigid(self)
}

assembly wine_rack {
    back_board = cradle_board(cradle_r=41 mm, dip=25 mm)
    neck_board = cradle_board(cradle_r=16 mm, dip=12 mm)
    solid neck_label_holder {
        # nothing: the label is engraved on the neck board below
    }
    left_leg = leg()
    right_leg = leg()

    drawing label {
        t = Text("SALUTE", position=(0, 40), size=14, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CutInto(label, neck_board)

    # flat layout
    Above(neck_board, back_board, gap=40)
    AlignLeft(neck_board, back_board)
    Below(left_leg, back_board, gap=10)
    AlignLeft(left_leg, back_board)
    RightOf(right_leg, left_leg, gap=10)
    AlignTop(right_leg, left_leg)

    # 3D: boards upright across, legs front to back under them
    Place(neck_board, position=(0, -board_gap / 2 + T / 2, 0), face="front", up="up")
    Place(back_board, position=(0, board_gap / 2 + T / 2, 0), face="front", up="up")
    Place(left_leg, position=(-leg_x - T / 2, 0, 0), face="right", up="up")
    Place(right_leg, position=(leg_x - T / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert len(back_board.cradles.c) == 4 and len(neck_board.cradles.c) == 4, "4 bottles"
    assert back_board.cradles.c[0].diameter == 82 mm, "body cradles 82"
    assert neck_board.cradles.c[0].diameter == 32 mm, "neck cradles 32"
    assert axis_h - back_board.body.bb.height == 41 mm - 25 mm, "body cradle 25 deep"
    assert axis_h - neck_board.body.bb.height == 16 mm - 12 mm, "neck cradle 12 deep"
    assert back_board.body.bb.width == 400 mm, "boards 400 long"
    assert pitch - 80 mm >= 10 mm, "bottles (80) clear each other"
    assert axis_h - 80 mm / 2 - leg_h >= 3 mm, "bottles clear the legs"
    assert back_board.cradles.c[3].center.x + 41 mm <= board_len / 2 - 10 mm, "end cradle inside the board"
}
