# Request: a tilt-back stand for my 1x12 guitar combo amp (450 wide x 250 deep), 6 mm ply,
# flat-pack, no glue.
# - Two side frames 300 mm long on the floor, 30 mm tall at the back, their top edge rising
#   toward the front at 15 deg (so the speaker points up at me).
# - At the back end of each side a stop post 16 mm thick standing square to the slope,
#   60 mm above it, that the amp's back rests against.
# - Two cross bars 420 x 40 mm, square to the slope, 250 mm and 60 mm along the slope from
#   the back end; sides 360 mm apart (centre to centre); every joint a cross-halving,
#   20 mm into the side and 20 mm into the bar, so the bars stand 20 mm proud of the slope
#   and the amp sits on them.
# - "AMP STAND  15 DEG" engraved 8 mm high on the front bar.
import "std/joints.aidl"

thickness 6 mm

t = 6 mm
tilt = 15 deg
ca = cos(tilt)
sa = sin(tilt)
side_l = 300 mm
back_h = 30 mm
post_w = 16 mm
post_up = 60 mm
bar_l = 420 mm
bar_h = 40 mm
halve = 20 mm
spacing = 360 mm
s_front = 250 mm
s_rear = 60 mm

def on_slope(s) = (s * ca, back_h + s * sa)           # a point s along the top edge
def below_slope(s, d) = (s * ca + d * sa, back_h + s * sa - d * ca)   # d square below it

def side_frame() -> solid {
    body = Polygon([(0, 0), (side_l, 0), (side_l, back_h + side_l * tan(tilt)), (0, back_h)])
    # the post: square to the slope, from 20 mm below it to 60 mm above it
    post = Rectangle(center=(post_w / 2 * ca - (post_up - halve) / 2 * sa,
                             back_h + post_w / 2 * sa + (post_up - halve) / 2 * ca),
                     width=post_w, height=post_up + halve, rotation=tilt)
    front_slot = cross_halving(depth=halve, thickness=t, rotation=tilt,
                               cx=on_slope(s_front)[0], cy=on_slope(s_front)[1])
    rear_slot = cross_halving(depth=halve, thickness=t, rotation=tilt,
                              cx=on_slope(s_rear)[0], cy=on_slope(s_rear)[1])
}

def cross_bar() -> solid {
    board = Rectangle(bottom_left=(-bar_l / 2, 0), width=bar_l, height=bar_h)
    for sx in [-1, 1] {
        notch = cross_halving(depth=bar_h - halve, thickness=t, rotation=180 deg,
                              cx=sx * spacing / 2, cy=0)
    }
}

assembly amp_stand {
    left = side_frame()
    right = side_frame()
    front_bar = cross_bar()
    rear_bar = cross_bar()
    drawing label {
        words = Text("AMP STAND  15 DEG", position=(0, bar_h / 2), size=8, valign="middle")
    }
    AlignCenterX(label, front_bar.board)
    AlignCenterY(label, front_bar.board)
    CutInto(label, front_bar)

    # flat on the sheet
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Below(front_bar, left, gap=10)
    AlignLeft(front_bar, left)
    Below(rear_bar, front_bar, gap=10)
    AlignLeft(rear_bar, front_bar)

    # 3D: x across, the back at y = +150, the sides' middles at x = -180 and +180
    Place(left, position=(-spacing / 2 + t / 2, side_l / 2, 0), face="left", up="up")
    Place(right, position=(spacing / 2 + t / 2, side_l / 2, 0), face="left", up="up")
    # a bar's bottom edge at the bottom of the sides' slot, its faces square to the slope
    Place(front_bar, position=(0, side_l / 2 - below_slope(s_front, halve)[0] + t / 2 * ca,
                               below_slope(s_front, halve)[1] - t / 2 * sa),
          face=(0, -ca, sa), up=(0, sa, ca))
    Place(rear_bar, position=(0, side_l / 2 - below_slope(s_rear, halve)[0] + t / 2 * ca,
                              below_slope(s_rear, halve)[1] - t / 2 * sa),
          face=(0, -ca, sa), up=(0, sa, ca))

    # the request's numbers
    assert left.body.bb.width == 300 mm, "sides 300 mm long"
    assert left.body.points[3].y - left.body.points[0].y == 30 mm, "30 mm tall at the back"
    assert abs(atan((left.body.points[2].y - left.body.points[3].y) / left.body.bb.width)
               - 15 deg) < 0.01 deg, "slope 15 deg"
    assert front_bar.board.width == 420 mm and front_bar.board.height == 40 mm, "bars 420 x 40"
    assert front_bar.notch[1].cut.center.x - front_bar.notch[0].cut.center.x == 360 mm,
        "sides 360 mm apart"
    assert spacing + t <= 450 mm, "the amp (450 wide) spans the sides"
    assert s_front - post_w <= 250 mm and s_front + t / 2 - post_w <= 250 mm, "front bar under the amp"
}
