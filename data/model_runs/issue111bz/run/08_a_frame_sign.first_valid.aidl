# Request (signs): a counter-top A-frame sign for a cafe, folded from ONE strip of 3 mm birch ply
# by a living hinge at the top, standing with 30 deg between its faces.
# - The strip 250 mm wide: two flat faces 400 mm long, and between them a living-hinge band
#   that bends the strip 150 deg round an 8 mm inside radius (the band as long as that bend).
# - Front face, outside: a clear 3 mm acrylic cover 226 x 313 mm (an A4 menu plus 8 mm all
#   round), corners r4, 20 mm above the bottom edge, centred, held by four M3 screws 6 mm in
#   from its corners (3.4 mm holes in cover and face); above it "TODAY'S SPECIALS" engraved
#   filled (bold), at most 226 mm long.
# - Back face: "OPEN" cut out as a stencil, 200 mm long at most, centred 200 mm above the
#   bottom edge, read from behind.
# - A 4 mm hole 10 mm above the bottom edge and 12 mm in from each side, on both faces, for a
#   cord that keeps the feet from spreading.
# Everything engraved is on the outside: the top of the sheet, so the hinge bends away from it.
import "std/plates.aidl"

thickness 3 mm

T = 3 mm
W = 250 mm
FACE = 400 mm
FOLD = 150 deg
R_IN = 8 mm
BAND = (FOLD / 1 rad) * (R_IN + T / 2)   # bend length on the sheet
X0 = FACE + BAND / 2                      # strip end (a face's bottom edge) from the fold line
COVER_W = 226 mm                          # across the face (strip's y)
COVER_H = 313 mm                          # up the face (strip's x)
COVER_UP = 20 mm
LEAN = 15 deg

# a face's point h above its bottom edge: front (x < 0) and back (x > 0)
def front_x(h) = -X0 + h
def back_x(h) = X0 - h

def screw_hole() -> hole {
    c = Circle(center=(0, 0), diameter=3.4)
}

assembly a_frame {
    solid strip {
        body = Rectangle(center=(0, 0), width=2 * X0, height=W)
        hinge = living_hinge(width=BAND, height=W, pitch=2 mm, cut=15 mm, bridge=3 mm)
        CenterInside(hinge, body)

        # front face: cover screws, cord holes, title
        seat = Rectangle(center=(front_x(COVER_UP + COVER_H / 2), 0), width=COVER_H,
                         height=COVER_W, construction=true)
        s = screw_hole()
        screws = CornerPattern(s, seat, inset=6)
        hole cords {
            fl = Circle(center=(front_x(10), W / 2 - 12), diameter=4)
            fr = Circle(center=(front_x(10), -W / 2 + 12), diameter=4)
            bl = Circle(center=(back_x(10), W / 2 - 12), diameter=4)
            br = Circle(center=(back_x(10), -W / 2 + 12), diameter=4)
        }
        drawing title {
            # standing, the front face's up is +x and its right (seen from the front) is -y
            t = Text("TODAY'S SPECIALS", position=(front_x(COVER_UP + COVER_H + 33), 0), size=20,
                     font="sans:Bold", valign="middle", fill=true, rotation=-90 deg,
                     max_width=COVER_W)
        }
        # back face: the back's up is -x, its right (seen from behind) is +y
        hole open {
            t = Text("OPEN", position=(back_x(200), 0), size=90, font="sans:Bold",
                     valign="middle", rotation=90 deg, stencil=true, max_width=200 mm)
        }
        Fixed(body)

        assert body.bb.height == 250 mm, "250 mm wide"
        assert hinge.bb.left - body.bb.left >= 400 mm - 1 mm, "flat faces 400 mm"
        assert seat.bb.left - body.bb.left == 20 mm, "cover 20 mm above the bottom"
        assert screws[0].c.center.x - seat.bb.left == 6 mm, "screws 6 mm in"
        assert title.bb.left >= seat.bb.right + 5 mm, "title above the cover"
        assert title.bb.right <= hinge.bb.left - 5 mm, "title below the hinge"
        assert title.bb.height <= 226 mm, "title at most 226 mm"
        assert open.bb.height <= 200 mm, "OPEN at most 200 mm"
        assert cords.fl.center.x - body.bb.left == 10 mm, "cord holes 10 mm up"
        assert body.bb.top - cords.fl.center.y == 12 mm, "cord holes 12 mm in"
    }

    solid cover {
        thickness 3 mm
        plate = RoundedRectangle(center=(front_x(COVER_UP + COVER_H / 2), 0), width=COVER_H,
                                 height=COVER_W, corner_radius=4)
        s = screw_hole()
        screws = CornerPattern(s, plate, inset=6)
        Fixed(plate)
        assert plate.width - 297 mm == 16 mm and plate.height - 210 mm == 16 mm, "A4 + 8 mm all round"
    }

    # 3D: the front face leans 15 deg back; local x runs up it, local y to world -x, the top
    # face (z = T) outward; its bottom edge on the table
    Place(strip, position=(0, 0, X0 * cos(LEAN)), rotation=(0, -75 deg, 90 deg))
    Bend(strip, at=0, angle=-FOLD, radius=R_IN)
    # the cover on the front face's outside (T further along the outward normal (0, -cos, sin))
    Place(cover, position=(0, -T * cos(LEAN), X0 * cos(LEAN) + T * sin(LEAN)),
          rotation=(0, -75 deg, 90 deg))

    # flat on the sheet
    Below(cover, strip, gap=10)
    AlignLeft(cover, strip)
}
