# Request (signs): a two-layer "BEWARE OF THE DOG" sign for the garden gate, 3 mm acrylic.
# - Backing: black acrylic, 300 x 120 mm, corners r10, two 4.5 mm screw holes 12 mm in
#   from the ends at mid height.
# - Face: yellow acrylic of the same size and holes, glued on the backing; cut through it
#   (so the black shows): "BEWARE OF" 20 mm high and "THE DOG" 30 mm high in bold stencil
#   letters, each line at most 190 mm wide, centred 30 mm right of the middle, their middles
#   20 mm above and 22 mm below the centre; and a paw print on the left, centred 105 mm left
#   of the middle: a 28 x 24 mm pad and four 11 x 14 mm toes.

thickness 3 mm

assembly sign {
    solid backing {
        plate = RoundedRectangle(center=(0, 0), width=300, height=120, corner_radius=10)
        hole screw { c = Circle(center=(-138, 0), diameter=4.5) }
        screws = LinearPattern(screw, 2, (276, 0))
        Fixed(plate)
    }

    solid face {
        plate = RoundedRectangle(center=(0, 0), width=300, height=120, corner_radius=10)
        hole screw { c = Circle(center=(-138, 0), diameter=4.5) }
        screws = LinearPattern(screw, 2, (276, 0))
        hole words {
            top = Text("BEWARE OF", position=(30, 20), size=20, valign="middle",
                       font="sans:Bold", stencil=true, max_width=190)
            bottom = Text("THE DOG", position=(30, -22), size=30, valign="middle",
                          font="sans:Bold", stencil=true, max_width=190)
        }
        hole paw {
            pad = Ellipse(center=(-105, -8), rx=14, ry=12)
            toe_1 = Ellipse(center=(-125, 6), rx=5.5, ry=7, rotation=20 deg)
            toe_2 = Ellipse(center=(-112, 17), rx=5.5, ry=7)
            toe_3 = Ellipse(center=(-98, 17), rx=5.5, ry=7)
            toe_4 = Ellipse(center=(-85, 6), rx=5.5, ry=7, rotation=-20 deg)
        }
        Fixed(plate)
    }

    # flat: the face under the backing
    Below(face, backing, gap=6)
    AlignCenterX(face, backing)
    # 3D: the face glued on the backing
    Place(backing, position=(0, 0, 0))
    Place(face, position=(0, 0, 3))

    assert backing.plate.width == 300 mm and backing.plate.height == 120 mm
    assert backing.screws[0].c.center.x - backing.plate.bb.left == 12 mm
    assert backing.plate.bb.right - backing.screws[1].c.center.x == 12 mm
    # as written, the two layers' holes line up
    assert face.screws[0].c.center.x == backing.screws[0].c.center.x
    assert face.screws[1].c.center.x == backing.screws[1].c.center.x
    assert face.words.top.bb.width <= 190 mm and face.words.bottom.bb.width <= 190 mm
    assert face.words.top.position.x - face.plate.center.x == 30 mm
    assert face.paw.pad.rx * 2 == 28 mm and face.paw.pad.ry * 2 == 24 mm
    # the paw stays clear of the screw hole and of the words
    assert face.paw.bb.left > face.screws[0].c.center.x + 2.25 mm + 3 mm
    assert face.paw.bb.right + 3 mm < face.words.bb.left
}
