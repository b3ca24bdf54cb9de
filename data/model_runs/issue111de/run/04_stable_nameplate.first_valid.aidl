# Request: a stable-door nameplate for a horse called MAPLE, in three glued layers.
# - Backing: 6 mm oak-veneered ply, 300 x 100 mm, corners rounded R20, two M4 countersunk
#   screw holes (9 mm heads) on the centre line 20 mm in from each end, and a border line
#   engraved 6 mm in from the edge (corners R14).
# - Name: "MAPLE" in bold serif, 45 mm capitals, cut from 3 mm black acrylic as one piece: the
#   letters stand on a 4 mm rail as long as the word; centred 20 mm right of the plate's
#   middle, baseline 28 mm above the plate's bottom edge; at most 170 mm long.
# - Horseshoe: 3 mm gold acrylic, 40 mm across (outer R20, inner R12), open end up (a 60 deg
#   opening), six 2.5 mm nail holes on R16, its centre 95 mm left of the plate's middle,
#   level with it.
# The name and horseshoe must clear the screw heads and each other by at least 10 mm.

import "std/fasteners.aidl"

thickness 3 mm

param horse = "MAPLE"

assembly nameplate {
    solid backing {
        thickness 6 mm
        body = RoundedRectangle(center=(0, 0), width=300, height=100, corner_radius=20)
        left_screw = clearance_hole(size=4, cx=-130 mm, cy=0 mm)
        right_screw = clearance_hole(size=4, cx=130 mm, cy=0 mm)
        Countersink([left_screw, right_screw], diameter=9 mm)
        Fixed(body)
        drawing border {
            line = RoundedRectangle(center=(0, 0), width=300 - 12, height=100 - 12, corner_radius=14)
        }
    }

    solid name {
        word = Text(horse, position=(20, -50 + 28), size=45, font="serif:Bold", max_width=170)
        rail = Rectangle(center=(word.center.x, -50 + 28 - 1.5), width=word.bb.width, height=4)
    }

    solid shoe {
        band = Sector(center=(-95, 0), radius=20, start_angle=120 deg, end_angle=60 deg,
                      inner_radius=12)
        hole nails {
            for a in [150, 190, 230, 310, 350, 30] {
                n = Circle(center=(-95 + 16 * cos(a * 1 deg), 16 * sin(a * 1 deg)), diameter=2.5)
            }
        }
        Fixed(band)
    }

    # on the sheet: the two acrylic layers below the backing
    Below(name, backing, gap=6)
    AlignLeft(name, backing)
    RightOf(shoe, name, gap=6)
    AlignTop(shoe, name)

    # in 3D: on the door (the plane y = 0), the layers glued on the backing's front face
    Place(backing, position=(0, 0, 0), face="front", up="up")
    Place(name, position=(0, -6, 0), face="front", up="up")
    Place(shoe, position=(0, -6, 0), face="front", up="up")

    assert backing.body.bb.width == 300 mm and backing.body.bb.height == 100 mm, "300 x 100"
    assert backing.right_screw.c.center.x - backing.left_screw.c.center.x == 260 mm, "20 in from each end"
    assert name.word.size <= 45 mm, "45 mm capitals at most"
    assert name.word.bb.width <= 170 mm, "at most 170 long"
    assert name.word.position.x == 20 mm and name.word.position.y == -50 mm + 28 mm, "name placed"
    assert shoe.band.bb.width == 40 mm, "shoe 40 across"
    assert len(shoe.nails.n) == 6, "six nail holes"
    # clearances, in the plate's frame (both layers are written in it)
    assert name.word.bb.left - shoe.band.bb.right >= 10 mm, "name clears the shoe"
    assert shoe.band.bb.left - (-130 mm + 4.5 mm) >= 10 mm, "shoe clears the left screw head"
    assert (130 mm - 4.5 mm) - name.word.bb.right >= 10 mm, "name clears the right screw head"
}
