# Request (crafts): a table inkle loom in 9 mm birch ply. Two side frames 500 long x 300
# tall with R10 outer corners, each a 40 mm wide border round a window with R15 corners.
# Six 12 mm dowel pegs pass through both frames (holes 12.2 mm) at (20, 20), (20, 280),
# (250, 280), (480, 280), (480, 200) and (480, 20), measured from the frame's bottom-left
# corner; the tension peg is an M8 bolt in an 8.5 mm slot in the front stile at x = 20,
# travelling 80 mm (centres from y = 100 to 180). Three cross bars, 40 tall, hold the frames
# 150 mm apart (inside): two in the bottom rail at x = 120 and 380, one in the back stile
# at x = 480 centred 80 up; each bar has a single 30 mm through tenon at each end. The
# outer face of the front frame has ELSIE'S LOOM engraved filled in serif, 14 mm capitals,
# centred on the bottom rail. Five parts.

import "std/joints.aidl"

thickness 9 mm

param inside = 150 mm, min = 80 mm, max = 300 mm
pegs = [(20, 20), (20, 280), (250, 280), (480, 280), (480, 200), (480, 20)]
bars = [(120, 20), (380, 20), (480, 80)]

def side_frame(name="") -> solid {
    outline = RoundedRectangle(bottom_left=(0, 0), width=500, height=300, corner_radius=10)
    hole window {
        w = RoundedRectangle(bottom_left=(40, 40), width=420, height=220, corner_radius=15)
    }
    hole peg_holes {
        for p in pegs {
            c = Circle(center=p, diameter=12.2)
        }
    }
    hole tension {
        s = Slot(start=(20, 100), end=(20, 180), width=8.5)
    }
    for b in bars {
        mortise = tab_and_slot(part="slot", length=40 mm, thickness=9 mm, tabs=1, tab=30 mm,
                               screw=0, rotation=90 deg, cx=b[0], cy=b[1])
    }
    if name != "" {
        drawing label {
            t = Text(name, position=(250, 20), size=14, font="serif", valign="middle",
                     fill=true)
        }
    }
}

# a cross bar: x along it (between the frames), y up; its tenons' tips 9 mm past each end
def cross_bar() -> solid {
    body = Rectangle(center=(0, 0), width=inside + 18 mm, height=40)
    left_end = tab_and_slot(part="tab", length=40 mm, thickness=9 mm, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=-inside / 2 - 9 mm, cy=0 mm)
    right_end = tab_and_slot(part="tab", length=40 mm, thickness=9 mm, tabs=1, tab=30 mm,
                             screw=0, rotation=-90 deg, cx=inside / 2 + 9 mm, cy=0 mm)
}

assembly loom {
    front = side_frame(name="ELSIE'S LOOM")
    back = side_frame()
    bar0 = cross_bar()
    bar1 = cross_bar()
    bar2 = cross_bar()

    # flat on the sheet
    Below(back, front, gap=10)
    AlignLeft(back, front)
    RightOf(bar0, front, gap=10)
    AlignTop(bar0, front)
    Below(bar1, bar0, gap=10)
    AlignLeft(bar1, bar0)
    Below(bar2, bar1, gap=10)
    AlignLeft(bar2, bar1)

    # in 3D: both frames read the same way from the front (their pegs line up); the
    # front's engraved face looks out, the back's faces in; bars across between them
    Place(front, position=(-250, -inside / 2, 0), face="front", up="up")
    Place(back, position=(-250, inside / 2 + 9 mm, 0), face="front", up="up")
    Place(bar0, position=(-250 + bars[0][0] - 4.5 mm, 0, bars[0][1]), face="right", up="up")
    Place(bar1, position=(-250 + bars[1][0] - 4.5 mm, 0, bars[1][1]), face="right", up="up")
    Place(bar2, position=(-250 + bars[2][0] - 4.5 mm, 0, bars[2][1]), face="right", up="up")

    assert front.outline.bb.width == 500 mm and front.outline.bb.height == 300 mm,
        "frames 500 x 300"
    assert front.window.w.bb.left - front.outline.bb.left == 40 mm, "40 mm border"
    assert front.outline.bb.top - front.window.w.bb.top == 40 mm, "40 mm border at the top"
    assert len(front.peg_holes.c) == 6, "six pegs"
    assert front.peg_holes.c[0].diameter == 12.2 mm, "12.2 peg holes"
    assert front.tension.s.end.y - front.tension.s.start.y == 80 mm, "80 mm of tension travel"
    assert front.tension.s.width == 8.5 mm, "M8 slot"
    assert bar0.body.bb.width - 2 * 9 mm == 150 mm, "frames 150 apart inside"
    assert front.label.t.position.y - front.outline.bb.bottom == 20 mm, "label on the rail"
    assert min([distance(front.label, m) for m in front.mortise]) >= 5 mm, "label clear of the bar mortises"
}
