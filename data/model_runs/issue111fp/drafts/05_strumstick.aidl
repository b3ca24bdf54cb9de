# Request: a three-string strumstick (diatonic dulcimer-on-a-stick, tuned D-A-D) with a
# 500 mm scale, in 3 mm birch ply, built on a bought 25 x 20 mm hardwood neck stick that
# runs through the body. Body: a glued finger-jointed box 300 x 110 x 45 (outside); the
# stick passes through a 25.4 x 20 hole in each end wall, its top 3 mm below the box's top
# (just under the soundboard). Soundboard: two 28 mm sound holes, 65 mm from the neck end
# and 32 mm either side of the centre line, each ringed by an engraved circle 34 mm across;
# "STRUMSTICK" engraved near the tail. Fretboard 365 x 25, glued on the stick from the nut
# to the body: 12 diatonic frets (semitones 2 4 5 7 9 11 12 14 16 17 19 21) as tang slots
# 0.6 x 21 mm; filled 5 mm position dots at frets 3, 5 and 10 and a pair at fret 7 (the
# octave). Nut 25 x 5 with three notches 7 mm apart; bridge 60 wide at the foot (50 at the
# top) x 7 tall, with an arch 34 x 3 under it and three notches 10 mm apart, standing on
# the soundboard 500 mm from the nut.

import "std/joints.aidl"

thickness 3 mm

SCALE = 500 mm
SEMIS = [2, 4, 5, 7, 9, 11, 12, 14, 16, 17, 19, 21]
FRETS = [SCALE * (1 - 2 ** (-s / 12)) for s in SEMIS]
def dot_x(k) = (FRETS[k - 2] + FRETS[k - 1]) / 2

BOX_L = 300 mm
BOX_D = 110 mm
BOX_H = 45 mm
# assembled: the box stands centred on x = y = 0; the nut end of the fretboard 365 mm left
# of the box's left wall
NUT_X = -BOX_L / 2 - 365 mm
BRIDGE_X = NUT_X + SCALE
HOLE_X = -BOX_L / 2 + 65 mm

assembly strumstick {
    box = finger_box(length=BOX_L, depth=BOX_D, height=BOX_H, thickness=3 mm, finger=10 mm,
                     closed=true)

    # the stick's holes in the end walls; the sides lie with their top edge outward
    # (left wall: at -x; right wall: at +x), the box's depth along y
    hole neck_in { r = Rectangle(center=(0, 0), width=20, height=25.4) }
    neck_in.r.bb.left == box.left.bb.left + 3 mm
    AlignCenterY(neck_in, box.left)
    CutInto(neck_in, box.left)
    hole neck_out { r = Rectangle(center=(0, 0), width=20, height=25.4) }
    neck_out.r.bb.right == box.right.bb.right - 3 mm
    AlignCenterY(neck_out, box.right)
    CutInto(neck_out, box.right)

    # soundboard (the lid): drawn in box coordinates, the lid's centre at (0, 0)
    hole sound {
        mid = Point(0, 0, construction=true)
        a = Circle(center=(HOLE_X, 32), diameter=28)
        b = Circle(center=(HOLE_X, -32), diameter=28)
        Rigid(self)
    }
    Coincident(sound.mid, box.lid.bb.center)
    CutInto(sound, box.lid)
    drawing lid_art {
        mid = Point(0, 0, construction=true)
        ring_a = Circle(center=(HOLE_X, 32), diameter=34)
        ring_b = Circle(center=(HOLE_X, -32), diameter=34)
        name = Text("STRUMSTICK", position=(95, 0), size=6, valign="middle")
        Rigid(self)
    }
    Coincident(lid_art.mid, box.lid.bb.center)
    CutInto(lid_art, box.lid)

    solid fretboard {
        board = Rectangle(bottom_left=(0, -12.5), width=365, height=25)
        hole frets {
            for i in range(len(FRETS)) {
                s = Rectangle(center=(FRETS[i], 0), width=0.6, height=21)
            }
        }
        drawing dots {
            d3 = Circle(center=(dot_x(3), 0), diameter=5, fill=true)
            d5 = Circle(center=(dot_x(5), 0), diameter=5, fill=true)
            d7a = Circle(center=(dot_x(7), 6), diameter=5, fill=true)
            d7b = Circle(center=(dot_x(7), -6), diameter=5, fill=true)
            d10 = Circle(center=(dot_x(10), 0), diameter=5, fill=true)
        }
    }
    solid nut {
        block = Rectangle(bottom_left=(-12.5, 0), width=25, height=5)
        hole notches {
            for i in range(3) {
                n = Circle(center=(-7 + i * 7, 5), diameter=1.4)
            }
        }
    }
    solid bridge {
        body = Trapezoid(center=(0, 3.5), bottom_width=60, top_width=50, height=7)
        hole arch { r = Rectangle(center=(0, 0), width=34, height=6) }
        hole notches {
            for i in range(3) {
                n = Circle(center=(-10 + i * 10, 7), diameter=1.4)
            }
        }
    }

    # flat on the sheet: under the box's net
    Below(fretboard, box.front, gap=10)
    AlignLeft(fretboard, box.front)
    RightOf(nut, fretboard, gap=8)
    AlignTop(nut, fretboard)
    Below(bridge, nut, gap=8)
    AlignLeft(bridge, nut)

    # in 3D: the stick's top at z 42 (3 below the box's top), the fretboard on it
    Place(fretboard, position=(NUT_X, 0, 42), face="up")
    Place(nut, position=(NUT_X - 3 mm, 0, 42), face="right", up="up")
    Place(bridge, position=(BRIDGE_X - 1.5 mm, 0, 45), face="right", up="up")

    # the request's numbers
    assert len(FRETS) == 12, "12 frets"
    assert abs(FRETS[6] - 250 mm) < 0.01 mm, "the octave (fret 7) at half the scale"
    assert FRETS[11] <= 365 mm - 5 mm, "the last fret on the fretboard"
    assert BRIDGE_X - NUT_X == 500 mm, "scale 500"
    assert BRIDGE_X > -BOX_L / 2 + 20 mm and BRIDGE_X < BOX_L / 2 - 20 mm, "bridge on the body"
    assert BRIDGE_X - HOLE_X >= 14 mm + 20 mm, "bridge clear of the sound holes"
    assert fretboard.board.width == 365 mm and fretboard.board.height == 25 mm, "fretboard"
    assert 32 mm - 14 mm >= 25.4 mm / 2 + 3 mm, "sound holes clear of the stick below"
    assert bridge.body.height == 7 mm and bridge.body.bottom_width == 60 mm, "bridge size"
    assert nut.block.width == 25 mm, "nut as wide as the fretboard"
}
