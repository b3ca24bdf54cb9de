# Request: a toad house for the shady corner under the hedge. Open bottom, 150 mm
# wide and 120 mm deep, walls 100 mm high, a pitched roof with the ridge at 140 mm.
# The front has an arched doorway 60 mm wide and 55 mm high opening at the ground,
# a 25 mm round window and "TOAD HALL" engraved over the door; the back has one
# 25 mm window. The walls are finger-jointed at the corners; the roof is one piece
# that bends over the ridge on a living hinge and overhangs the walls by 12 mm.
# 4 mm exterior ply, glued.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 4 mm

param t = 4 mm, min = 3 mm, max = 6 mm
param W = 150 mm, min = 120 mm, max = 200 mm     # front width
param D = 120 mm, min = 90 mm, max = 160 mm      # depth (the sides)
param H = 100 mm, min = 80 mm, max = 130 mm      # wall height
param ridge = 140 mm, min = 110 mm, max = 180 mm
param overhang = 12 mm, min = 5 mm, max = 25 mm

finger = 12 mm
pitch_a = atan((ridge - H) / (W / 2))            # roof pitch
slope = sqrt((W / 2) ** 2 + (ridge - H) ** 2)    # gable's sloped edge
band = 14 mm                                     # the hinge band across the ridge
bend_r = band / (2 * pitch_a / 1 rad) - t / 2    # inside radius that needs this band
tangent = bend_r * tan(pitch_a)                  # where the bend leaves each slope
roof_w = band + 2 * (slope - tangent + overhang)
roof_d = D + 2 * overhang

def gable(front=true) -> solid {
    body = Polygon([(-W / 2, 0), (W / 2, 0), (W / 2, H), (0, ridge), (-W / 2, H)])
    # FIX after the first valid program: the sharp apex poked 0.185 mm into the bent roof
    # (W0517): rounded to the hinge's inside radius, so the roof bears along it
    Fillet(body.points[3], bend_r)
    fl = finger_edge(length=H, thickness=t, finger=finger, start="tab",
                     rotation=90 deg, cx=-W / 2, cy=H / 2)
    fr = finger_edge(length=H, thickness=t, finger=finger, start="tab",
                     rotation=-90 deg, cx=W / 2, cy=H / 2)
    if front {
        hole door {
            r = Rectangle(corner=(-30, 0), opposite=(30, 25))
            c = Circle(center=(0, 25), radius=30)
            o = Rectangle(corner=(-30, -1), opposite=(30, 0.5), overrun=true)
        }
        hole window {
            c = Circle(center=(42, 62), diameter=25)
        }
        drawing name {
            w = Text("TOAD HALL", position=(0, 112), size=8, valign="middle")
        }
    } else {
        hole window {
            c = Circle(center=(-30, 66), diameter=25)
        }
    }
}

def side() -> solid {
    body = Rectangle(corner=(-D / 2, 0), opposite=(D / 2, H))
    fl = finger_edge(length=H, thickness=t, finger=finger, start="gap",
                     rotation=90 deg, cx=-D / 2, cy=H / 2)
    fr = finger_edge(length=H, thickness=t, finger=finger, start="gap",
                     rotation=-90 deg, cx=D / 2, cy=H / 2)
}

assembly toad_house {
    front = gable(front=true)
    back = gable(front=false)
    left = side()
    right = side()
    solid roof {
        sheet = Rectangle(center=(0, 0), width=roof_w, height=roof_d)
        hinge = living_hinge(width=band, height=roof_d, pitch=2 mm, cut=15 mm,
                             bridge=3 mm, cx=0, cy=0)
    }

    # on the sheet
    RightOf(back, front, gap=6)
    AlignBottom(back, front)
    Below(left, front, gap=6)
    AlignLeft(left, front)
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    RightOf(roof, back, gap=6)
    AlignTop(roof, back)

    # assembled: X across the front, Y from the front (-Y) to the back, Z up
    Place(front, position=(0, -D / 2 + t, 0), face="front", up="up")
    Place(back, position=(0, D / 2 - t, 0), face="back", up="up")
    Place(left, position=(-W / 2 + t, 0, 0), face="left", up="up")
    Place(right, position=(W / 2 - t, 0, 0), face="right", up="up")
    # FIX after the first valid program: W0517 (roof 0.67 mm into both gables): the bend
    # starts `tangent` down each slope, so the roof's frame sits (band / 2 - tangent) along
    # the slope from the apex, not on it (a 0.2 mm lift tried against a W0517 of 26 mm^3
    # at the apex: W0518 0.176 mm away, so the apex is rounded instead, see gable)
    Place(roof, position=((band / 2 - tangent) * cos(pitch_a), 0,
                          ridge + (band / 2 - tangent) * sin(pitch_a)),
          rotation=(0, -pitch_a, 0))
    Bend(roof, at=0, angle=-2 * pitch_a, radius=bend_r)

    # the request's numbers
    assert front.body.bb.width == 150 mm, "150 mm wide"
    assert left.body.bb.width == 120 mm, "120 mm deep"
    assert left.body.bb.height == 100 mm, "walls 100 mm high"
    assert front.body.bb.height == 140 mm, "ridge at 140 mm"
    assert front.door.bb.width == 60 mm, "door 60 mm wide"
    assert front.door.bb.top - front.body.bb.bottom == 55 mm, "door 55 mm high"
    assert front.window.c.diameter == 25 mm and back.window.c.diameter == 25 mm, "25 mm windows"
    assert roof.sheet.bb.height - left.body.bb.width == 2 * 12 mm, "12 mm overhang front and back"
    assert band >= 2 * pitch_a / 1 rad * (bend_r + t / 2) - 0.01 mm, "the band covers the bend"
}
