# Request (holidays): a Dia de los Muertos sugar-skull wall decoration, two layers of 3 mm
# material. The front skull in birch ply is 150 mm wide and 180 mm tall: a round cranium and
# a narrower 90 mm jaw with rounded corners, two 40 mm eye sockets cut through (64 mm apart,
# centre to centre), each ringed by eight engraved filled petals, an upside-down heart nose
# cut through, a stitched mouth (a line with nine stitches) engraved, a six-petal flower
# engraved filled on the forehead and "ABUELA ROSA" engraved on the chin. A 5 mm hanging
# hole near the top. Behind it a coloured acrylic backing of the same outline 4 mm larger
# all round, with the same hanging hole, shows through the eyes and nose.

units mm
thickness 3 mm

eye_d = 40 mm
eye_dx = 32 mm      # half the eyes' spacing
eye_y = 10 mm
hang_y = 85 mm

assembly decoration {
    solid skull {
        cranium = Ellipse(center=(0, 25), rx=75, ry=70)
        jaw = RoundedRectangle(center=(0, -55), width=90, height=60, corner_radius=25)

        hole eyes {
            for s in [-1, 1] {
                e = Circle(center=(s * eye_dx, eye_y), diameter=eye_d)
            }
        }
        hole nose {
            l = Hull(Circle(center=(-4.5, -22), radius=5), Point(0, -9))
            r = Hull(Circle(center=(4.5, -22), radius=5), Point(0, -9))
        }
        hole hang { c = Circle(center=(0, hang_y), diameter=5) }

        drawing petals {
            for k in range(16) {
                p = Circle(center=((k // 8 * 2 - 1) * eye_dx + 26 * cos((k % 8) * 45 deg),
                                   eye_y + 26 * sin((k % 8) * 45 deg)), radius=3, fill=true)
            }
        }
        drawing flower {
            f = Star(center=(0, 60), points=6, outer_radius=14, inner_radius=7, tip_radius=3,
                     fill=true)
        }
        drawing mouth {
            m = Line((-38, -50), (38, -50))
            for i in range(9) {
                st = Line((-32 + i * 8, -55), (-32 + i * 8, -45))
            }
        }
        drawing name {
            n = Text("ABUELA ROSA", position=(0, -75), size=6)
        }

        # the request's numbers
        assert self.bb.width == 150 mm and self.bb.height == 180 mm, "150 x 180"
        assert jaw.bb.width == 90 mm, "90 mm jaw"
        assert eyes.e[0].diameter == 40 mm and eyes.e[1].center.x - eyes.e[0].center.x == 64 mm, "eyes"
        assert len(petals.p) == 16 and len(mouth.st) == 9, "eight petals per eye, nine stitches"
        assert hang.c.diameter == 5 mm, "5 mm hanging hole"
    }

    solid backing {
        cranium = Offset(Ellipse(center=(0, 25), rx=75, ry=70), 4)
        jaw = Offset(RoundedRectangle(center=(0, -55), width=90, height=60, corner_radius=25), 4)
        hole hang { c = Circle(center=(0, hang_y), diameter=5) }
        assert self.bb.width - 150 mm == 8 mm, "4 mm larger all round"
    }

    # flat on the sheet side by side; in 3D the backing behind, the skull on it
    RightOf(backing, skull, gap=10)
    AlignCenterY(backing, skull)
    Place(backing, position=(0, 0, 0), face="up")
    Place(skull, position=(0, 0, 3), face="up")
}
