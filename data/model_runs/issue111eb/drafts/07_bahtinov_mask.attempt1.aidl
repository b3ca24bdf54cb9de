# Request: a Bahtinov focusing mask for an 80 mm f/6 refractor (480 mm focal length) whose
# dew shield is 96 mm across, cut from 3 mm black acrylic. The mask is a 106 mm disc; inside
# an 80 mm aperture the grating: slits 1.6 mm wide at a 3.2 mm period (480 / 150), the top
# half's slits vertical, the bottom half split into two quadrants whose slits lean 20 deg
# either way from vertical; 4 mm bars between the three sections. A handle tab 16 mm wide
# sticks out 12 mm at the top. "BAHTINOV  480 mm" engraved (4 mm single-stroke, on a 93 mm
# circle, over the top) and "80 mm f/6" under it (at the bottom, reading the right way up).
# Two collar rings 106 / 96.4 mm (0.2 mm play on the dew shield) glued under the mask.

units mm
thickness 3 mm
import "std/shapes.aidl"

P = 3.2 mm      # slit period
SW = 1.6 mm     # slit width
AP = 40 mm      # aperture radius
LEAN = 20 deg

assembly kit {
    solid mask {
        disc = Circle(center=(0, 0), diameter=106)
        handle = Slot(center=(0, 53), length=24, width=16, rotation=90 deg)
        hole grating {
            for k in range(-12, 13) {
                top = Intersect(Rectangle(center=(k * P, 0), width=SW, height=100),
                                Circle(center=(0, 0), radius=AP),
                                Rectangle(corner=(-45, 2), opposite=(45, 45)))
            }
            for k in range(-3, 12) {
                left = Intersect(Rectangle(center=polar((0, 0), k * P, 90 deg + 90 deg - LEAN),
                                           width=120, height=SW, rotation=90 deg - LEAN),
                                 Circle(center=(0, 0), radius=AP),
                                 Rectangle(corner=(-45, -45), opposite=(-2, -2)))
                right = Intersect(Rectangle(center=polar((0, 0), k * P, LEAN),
                                            width=120, height=SW, rotation=90 deg + LEAN),
                                  Circle(center=(0, 0), radius=AP),
                                  Rectangle(corner=(2, -45), opposite=(45, -2)))
            }
        }
        drawing words {
            ring = Circle(center=(0, 0), radius=46.5, construction=true)
            over = Text("BAHTINOV  480 mm", along=ring, size=4, valign="middle")
            under = Text("80 mm f/6", along=ring, size=4, valign="middle", flip=true)
        }
    }
    c1 = washer(outer=106, inner=96.4)
    c2 = washer(outer=106, inner=96.4)

    RightOf(c1, mask, gap=5)
    AlignBottom(c1, mask)
    RightOf(c2, c1, gap=5)
    AlignBottom(c2, c1)

    # assembled: the collars stacked under the mask, the mask's engraving up (outward)
    Place(c2, position=(0, 0, 0), rotation=(0, 0, 0))
    Place(c1, position=(0, 0, 3), rotation=(0, 0, 0))
    Place(mask, position=(0, 0, 6), rotation=(0, 0, 0))

    # the request's numbers
    assert mask.disc.diameter == 106 mm, "106 mm disc"
    assert len(mask.grating.top) == 25 and len(mask.grating.left) == 15 and len(mask.grating.right) == 15, "slit counts"
    assert mask.grating.bb.width <= 80 mm and mask.grating.bb.height <= 80 mm, "grating within the 80 mm aperture"
    assert distance(mask.grating.left, mask.grating.right) >= 4 mm, "4 mm bar between the quadrants"
    assert distance(mask.grating.top, mask.grating.left) >= 4 mm and distance(mask.grating.top, mask.grating.right) >= 4 mm, "4 mm bar under the top half"
    assert mask.handle.bb.top - mask.disc.bb.top == 12 mm and mask.handle.width == 16 mm, "handle 16 wide, 12 out"
    assert c1.ring.diameter == 106 mm and c1.bore.diameter == 96.4 mm, "collars 106 / 96.4"
    assert distance(mask.words, mask.grating) >= 3 mm, "words clear of the grating"
}
