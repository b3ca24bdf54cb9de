# Bathroom: a two-step perfume riser for the bathroom counter, cut from 4 mm birch ply.
# Overall 240 mm wide, 130 mm deep and 110 mm tall at the back. Two stepped side panels
# (front step 65 mm deep and 55 mm tall, back step up to 110 mm). A lower shelf 65 mm deep
# and an upper shelf (from the step to the back panel) sit 8 mm (centre) below each step's
# top, so the sides stand up as little rails; each shelf has 2 glued tabs 15 mm wide at each
# end through mortises in the sides. A back panel 240 x 160 mm (top corners R12) is finger
# jointed (fingers at least 10 mm) to the sides' back edges over their 110 mm and carries
# "PARFUMS" engraved as filled serif letters 18 mm tall in the 50 mm that rises above the
# sides. Assembly of 5 parts.

units mm
thickness 4 mm
import "std/joints.aidl"

param t = 4 mm, min = 3 mm, max = 6 mm
param width = 240 mm, min = 160 mm, max = 360 mm
param depth = 130 mm, min = 100 mm, max = 180 mm
param height = 110 mm, min = 80 mm, max = 160 mm
param step_h = 55 mm, min = 35 mm, max = 80 mm
param step_d = 65 mm, min = 45 mm, max = 90 mm
param back_h = 160 mm, min = 120 mm, max = 220 mm
param drop = 8 mm, min = 6 mm, max = 12 mm

def riser_side() -> solid {
    profile = Polygon([(0, 0), (depth, 0), (depth, height), (step_d, height), (step_d, step_h),
                       (0, step_h)])
    # the back edge fingers into the back panel
    fingers = finger_edge(length=height, thickness=t, finger=10 mm, start="tab", rotation=-90 deg,
                          cx=depth, cy=height / 2)
    # mortises for the two shelves' tabs
    low = tab_and_slot(part="slot", length=step_d, thickness=t, tabs=2, tab=15 mm, screw=0,
                       cx=step_d / 2, cy=step_h - drop)
    high = tab_and_slot(part="slot", length=depth - t - step_d, thickness=t, tabs=2, tab=15 mm,
                        screw=0, cx=(step_d + depth - t) / 2, cy=height - drop)
}

def shelf(d=65 mm) -> solid {
    board = Rectangle(center=(0, 0), width=width, height=d)
    left = tab_and_slot(part="tab", length=d, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=90 deg, cx=-width / 2, cy=0)
    right = tab_and_slot(part="tab", length=d, thickness=t, tabs=2, tab=15 mm, screw=0,
                         rotation=-90 deg, cx=width / 2, cy=0)
}

assembly riser {
    side_l = riser_side()
    side_r = riser_side()
    low = shelf(d=step_d)
    high = shelf(d=depth - t - step_d)

    solid back {
        panel = RoundedRectangle(center=(0, back_h / 2), width=width, height=back_h,
                                 corner_radii=[12, 12, 0, 0])
        l = finger_edge(length=height, thickness=t, finger=10 mm, start="gap", rotation=90 deg,
                        cx=-width / 2, cy=height / 2)
        r = finger_edge(length=height, thickness=t, finger=10 mm, start="gap", rotation=-90 deg,
                        cx=width / 2, cy=height / 2)
        drawing name {
            w = Text("PARFUMS", position=(0, (height + back_h) / 2), size=18, font="serif",
                     valign="middle", fill=true)
        }
    }

    # laid out flat for cutting
    RightOf(side_r, side_l, gap=10)
    RightOf(back, side_r, gap=10)
    AlignBottom(side_r, side_l)
    AlignBottom(back, side_l)
    Above(low, side_l, gap=10)
    AlignLeft(low, side_l)
    Above(high, low, gap=10)
    AlignLeft(high, low)

    # the request's own numbers
    assert back.panel.width == 240 mm and low.board.width == 240 mm and high.board.width == 240 mm, "240 mm wide overall"
    assert side_l.profile.bb.width == 130 mm, "130 mm deep"
    assert side_l.profile.bb.height == 110 mm, "110 mm tall at the back"
    assert side_l.profile.points[4].y - side_l.profile.points[0].y == 55 mm, "front step 55 mm tall"
    assert side_l.profile.points[4].x - side_l.profile.points[0].x == 65 mm, "front step 65 mm deep"
    assert low.board.height == 65 mm, "lower shelf 65 mm deep"
    assert high.board.height == 130 mm - 65 mm - 4 mm, "upper shelf from the step to the back panel"
    assert back.panel.height == 160 mm, "back panel 160 mm tall"
    assert back.panel.height - side_l.profile.bb.height == 50 mm, "back rises 50 mm above the sides"
    assert back.name.w.size == 18 mm, "letters 18 mm tall"
}
