# Request (toys): a rubber-band paddle boat for the bath or a pond, 6 mm marine ply.
# - Hull 200 mm long, 70 mm wide: a square stern and a pointed bow 80 mm long made of two
#   circular arcs (an ogive), so the straight sides run 120 mm from the stern.
# - At the stern a notch 46 mm wide and 60 mm deep for the paddle, leaving two arms 12 mm wide;
#   a rubber band is stretched across the arms, held in a 4 mm round notch in each arm's outer
#   edge 10 mm from the stern.
# - A 6 mm hole for a dowel mast on the centre line, 50 mm behind the bow tip.
# - The boat's name "PUDDLE JUMPER" engraved filled (bold) on the deck between the notch and the
#   mast, at most 60 mm long.
# - The paddle: two blades 40 x 50 mm, cross-halved (0.2 mm play) so they make a + seen from the
#   side, turning on the band: 3 mm clear of the notch on each side.
import "std/joints.aidl"

thickness 6 mm

T = 6 mm
L = 200 mm
W = 70 mm
BOW = 80 mm
R = (BOW ** 2 + (W / 2) ** 2) / W     # ogive radius: the arcs meet at the tip on the centre line
STERN_X = -(L - BOW)                  # the bow starts at x = 0
NOTCH_W = 46 mm
NOTCH_D = 60 mm
BAND_X = STERN_X + 10 mm
BLADE_W = 40 mm
BLADE_H = 50 mm

def blade(mouth_side=-1) -> solid {
    body = Rectangle(center=(0, 0), width=BLADE_W, height=BLADE_H)
    # halving slot from the side edge (mouth_side -1: left, +1: right) to the middle
    h = cross_halving(depth=BLADE_W / 2, thickness=T, clearance=0.2 mm,
                      rotation=(90 deg if mouth_side < 0 else -90 deg),
                      cx=mouth_side * BLADE_W / 2, cy=0 mm)
}

assembly paddle_boat {
    solid hull {
        stern = Rectangle(bottom_left=(STERN_X, -W / 2), width=L - BOW, height=W)
        bow = Intersect(Circle(center=(0, -(R - W / 2)), radius=R),
                        Circle(center=(0, R - W / 2), radius=R),
                        Rectangle(bottom_left=(0, -W / 2), width=BOW + 5, height=W))
        hole notch {
            r = Rectangle(bottom_left=(STERN_X - 1, -NOTCH_W / 2), width=NOTCH_D + 1, height=NOTCH_W)
        }
        hole band {
            a = Circle(center=(BAND_X, W / 2), diameter=4)
            b = Circle(center=(BAND_X, -W / 2), diameter=4)
        }
        hole mast {
            c = Circle(center=(BOW - 50, 0), diameter=6)
        }
        drawing name {
            t = Text("PUDDLE JUMPER", position=((STERN_X + NOTCH_D + BOW - 50) / 2, 0), size=8,
                     font="sans:Bold", valign="middle", fill=true, max_width=60 mm)
        }
        assert bow.bb.right - stern.bb.left == 200 mm, "200 mm long"
        assert stern.bb.height == 70 mm, "70 mm wide"
        assert bow.bb.right - bow.bb.left == 80 mm, "bow 80 mm"
        assert notch.r.bb.right - stern.bb.left == 60 mm, "notch 60 mm deep"
        assert notch.r.bb.height == 46 mm, "notch 46 mm wide"
        assert stern.bb.top - notch.r.bb.top == 12 mm, "arms 12 mm"
        assert band.a.center.x - stern.bb.left == 10 mm, "band notches 10 mm from the stern"
        assert bow.bb.right - mast.c.center.x == 50 mm, "mast 50 mm behind the bow tip"
        assert name.bb.width <= 60 mm, "name at most 60 mm"
        assert name.bb.left >= notch.r.bb.right + 3 mm, "name clear of the notch"
        assert name.bb.right <= mast.c.center.x - 6 mm, "name clear of the mast"
    }

    upright = blade(mouth_side=-1)
    flat = blade(mouth_side=1)

    assert (NOTCH_W - upright.body.bb.width) / 2 == 3 mm, "paddle 3 mm clear each side"
    assert upright.body.bb.width == 40 mm and upright.body.bb.height == 50 mm, "blade 40 x 50"

    # 3D: hull on the water (z 0..6); the paddle's axis along y at the band, mid-thickness
    Place(hull, position=(0, 0, 0))
    # upright blade: (u, v, w) -> (w, u, v): u across the boat, v up, thickness along x
    Place(upright, position=(BAND_X - T / 2, 0, T / 2), rotation=(90 deg, 0, 90 deg))
    # flat blade: (u, v, w) -> (-v, u, w): u across the boat, v along the boat, lying flat
    Place(flat, position=(BAND_X, 0, 0), rotation=(0, 0, 90 deg))

    # flat on the sheet
    RightOf(upright, hull, gap=5)
    RightOf(flat, upright, gap=5)
    AlignCenterY(upright, hull)
    AlignCenterY(flat, hull)
}
