# Request (office): a perpetual desk calendar in 3 mm birch ply.
# - two date cubes, 40 mm outside, finger-jointed (8 mm fingers); one digit on every face,
#   24 mm bold capitals engraved filled, centred: cube A 0 1 2 3 4 5, cube B 0 1 2 6 7 8
#   (the 6 turned over is the 9). The bottom panel's engraving faces in as cut, so its digit
#   is one that reads the same mirrored (0 on A, 8 on B) and the bottom is glued in turned
#   over, engraved face out.
# - twelve month tiles, 60 x 20 mm, each with a 40 x 3 mm tenon under it and the month's
#   name engraved filled, bold, at most 52 mm wide.
# - a base 130 x 80 mm in 6 mm ply: a 40.2 x 3.2 mm slot 15 mm from its front edge, centred,
#   where the current month stands; the two cubes' places engraved as 41 mm squares
#   behind it, 4 mm apart.
import "std/joints.aidl"

thickness 3 mm

CUBE = 40 mm
MONTHS = ["JANUARY", "FEBRUARY", "MARCH", "APRIL", "MAY", "JUNE", "JULY", "AUGUST",
          "SEPTEMBER", "OCTOBER", "NOVEMBER", "DECEMBER"]

def digit(s="0") -> drawing {
    t = Text(s, position=(0, 0), size=24, font="sans:Bold", valign="middle", fill=true)
}

def month_tile(name="JANUARY") -> solid {
    plate = Rectangle(center=(0, 10), width=60, height=20)
    tenon = Rectangle(center=(0, -1.5), width=40, height=3)
    drawing word {
        t = Text(name, position=(0, 10), size=9, font="sans:Bold", valign="middle",
                 max_width=52, fill=true)
    }
}

assembly calendar {
    a = finger_box(length=CUBE, depth=CUBE, height=CUBE, thickness=3 mm, finger=8 mm)
    b = finger_box(length=CUBE, depth=CUBE, height=CUBE, thickness=3 mm, finger=8 mm,
                   cx=150 mm, cy=0 mm)

    # cube A: 0 1 2 3 4 5
    a0 = digit(s="0")
    CenterInside(a0, a.bottom)
    CutInto(a0, a.bottom)
    a1 = digit(s="1")
    CenterInside(a1, a.front)
    CutInto(a1, a.front)
    a2 = digit(s="2")
    CenterInside(a2, a.back)
    CutInto(a2, a.back)
    a3 = digit(s="3")
    CenterInside(a3, a.left)
    CutInto(a3, a.left)
    a4 = digit(s="4")
    CenterInside(a4, a.right)
    CutInto(a4, a.right)
    a5 = digit(s="5")
    CenterInside(a5, a.lid)
    CutInto(a5, a.lid)

    # cube B: 0 1 2 6 7 8
    b8 = digit(s="8")
    CenterInside(b8, b.bottom)
    CutInto(b8, b.bottom)
    b1 = digit(s="1")
    CenterInside(b1, b.front)
    CutInto(b1, b.front)
    b2 = digit(s="2")
    CenterInside(b2, b.back)
    CutInto(b2, b.back)
    b6 = digit(s="6")
    CenterInside(b6, b.left)
    CutInto(b6, b.left)
    b7 = digit(s="7")
    CenterInside(b7, b.right)
    CutInto(b7, b.right)
    b0 = digit(s="0")
    CenterInside(b0, b.lid)
    CutInto(b0, b.lid)

    solid base {
        thickness 6 mm
        plate = RoundedRectangle(center=(320, 0), width=130, height=80, corner_radius=4)
        hole month_slot {
            s = Rectangle(center=(320, -25), width=40.2, height=3.2)
        }
        drawing places {
            left_sq = Rectangle(center=(320 - 22.5, 10), width=41, height=41)
            right_sq = Rectangle(center=(320 + 22.5, 10), width=41, height=41)
        }
    }

    for i in range(12) {
        tile = month_tile(name=MONTHS[i])
        tile.bb.center == (260 + (i % 3) * 66 mm, -80 - (i // 3) * 27 mm)
    }

    # FIX after the first valid program: W0517, the two cubes stood in one place assembled
    Place(b, position=(60, 0, 0))

    assert len(MONTHS) == 12, "twelve months"
    assert len(tile) == 12, "twelve tiles"
    assert a.front.bb.width == 40 mm, "cube 40 mm outside"
    assert base.plate.bb.width == 130 mm and base.plate.bb.height == 80 mm, "base 130 x 80"
    assert base.month_slot.s.bb.bottom - base.plate.bb.bottom == 15 mm - 1.6 mm,
        "slot centre 15 mm from the front edge"
    assert base.month_slot.s.width - tile[0].tenon.width == 0.2 mm, "0.1 mm each side"
    assert base.places.right_sq.bb.left - base.places.left_sq.bb.right == 4 mm,
        "cube places 4 mm apart"
    assert tile[8].word.t.size <= 9 mm, "SEPTEMBER fits"
}
