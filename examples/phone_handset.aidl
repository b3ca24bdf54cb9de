# A telephone handset in profile (side view): earpiece cup on the left,
# mouthpiece cup on the right, an arched handle between them. The outline is
# ten lines and arcs that share their end points, so together they form one
# closed shape; Horizontal/Vertical/Tangent/Symmetric keep its form.
# Try: --set length=220  --set cup_depth=45  --set corner=20

param length = 200 mm       # overall length
param cup_depth = 38 mm     # how far the cups reach below the handle's axis
param corner = 16 mm        # radius of the two rounded top corners
param handle_top = 16 mm    # top edge height above the axis

half = length / 2
face = 48 mm                # width of each cup's flat face
arch = 40 mm                # half-span of the arch under the handle

solid handset {
    solid body {
        p1 = Point(-half, -cup_depth)              # earpiece face, outer end
        p2 = Point(-half + face, -cup_depth)       # earpiece face, inner end
        p3 = Point(-arch, -8)                      # arch, left foot
        p4 = Point(arch, -8)                       # arch, right foot
        p5 = Point(half - face, -cup_depth)        # mouthpiece face, inner end
        p6 = Point(half, -cup_depth)               # mouthpiece face, outer end
        p7 = Point(half, handle_top - corner)      # right corner, start
        p8 = Point(half - corner, handle_top)      # right corner, end
        p9 = Point(-half + corner, handle_top)     # left corner, start
        p10 = Point(-half, handle_top - corner)    # left corner, end

        ear_face = Line(p1, p2)
        ear_inner = Line(p2, p3)
        under = Arc(center=(0, -90), start=p4, end=p3)        # the arch, bulging up
        mouth_inner = Line(p4, p5)
        mouth_face = Line(p5, p6)
        mouth_back = Line(p6, p7)
        right_corner = Arc(center=(half - corner, handle_top - corner), start=p7, end=p8)
        top = Line(p8, p9)
        left_corner = Arc(center=(-half + corner, handle_top - corner), start=p9, end=p10)
        ear_back = Line(p10, p1)

        axis = Line((0, -cup_depth), (0, handle_top), construction=true)

        Horizontal(ear_face)
        Horizontal(mouth_face)
        Horizontal(top)
        Vertical(ear_back)
        Vertical(mouth_back)
        Vertical(axis)
        Tangent(top, right_corner)
        Tangent(top, left_corner)
        Tangent(mouth_back, right_corner)
        Tangent(ear_back, left_corner)
        Symmetric(p3, p4, axis)
        Equal(ear_face, mouth_face)
    }

    # speaker grille in the earpiece cup: a row of small holes made by a loop
    hole grille {
        for i in range(4) {
            dot = Circle(center=(-half + 10 + i * 8 mm, -cup_depth + 9), radius=2.2)
        }
    }

    # microphone port in the mouthpiece cup
    hole mic {
        port = Circle(center=(half - face / 2, -cup_depth + 12), radius=4)
    }

    # engraved seam along the handle
    drawing seam {
        s = Line((-half + corner, handle_top - 5), (half - corner, handle_top - 5))
    }

    grille.bb.bottom == body.ear_face.start.y + 6.8
    grille.bb.left == body.ear_face.start.x + 7.8
    mic.port.center.x == body.mouth_face.midpoint.x
    mic.port.center.y == body.mouth_face.midpoint.y + 12
    AlignCenterX(seam, body.top)
    seam.bb.top == body.top.start.y - 5
}
