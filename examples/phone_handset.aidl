# A telephone handset in profile (side view): an arched handle of even
# thickness with a flared earpiece cup on the left and a mouthpiece cup on
# the right, both facing down. The outline is eight lines and arcs that
# share their end points, so together they form one closed shape;
# Horizontal, Concentric, Symmetric and Equal keep its form.
# Try: --set length=240  --set cup_depth=60  --set thickness=18

param length = 210 mm    # across the two cup faces
param cup_depth = 50 mm  # how far the cup faces sit below the handle's ends
param thickness = 24 mm  # thickness of the arched handle
param face = 56 mm       # width of each cup's face

half = length / 2
bend = 120 mm                                                   # the arch's center lies this far below the axis
neck = 38 mm                                                    # width of a cup where it joins the handle
r_in = sqrt(square(half - face + 9 mm) + square(bend - 20 mm))  # arch underside radius
r_out = r_in + thickness
gx = sqrt(square(r_out) - square(bend - 18 mm))    # handle top meets the cups' backs
rim = 5 mm                                         # cap rims, this far above the faces
rim_out = (half - gx) * rim / (cup_depth - 18 mm)  # where a rim meets the outer side
rim_in = 9 mm * rim / (cup_depth - 20 mm)          # ... and the inner side

solid handset {
    solid body {
        # outline points, counter-clockwise from the earpiece face's outer end
        a = Point(-half, -cup_depth)         # earpiece face, outer end
        b = Point(-half + face, -cup_depth)  # earpiece face, inner end
        c = Point(-half + face - 9 mm, -20)  # arch underside, left foot
        d = Point(half - face + 9 mm, -20)   # arch underside, right foot
        e = Point(half - face, -cup_depth)   # mouthpiece face, inner end
        f = Point(half, -cup_depth)          # mouthpiece face, outer end
        g = Point(gx, -18)                   # handle top, right end
        h = Point(-gx, -18)                  # handle top, left end
        o = Point(0, -bend)                  # center of the arch

        ear_face = Line(a, b)
        ear_inner = Line(b, c)
        under = Arc(center=o, start=d, end=c)  # underside of the handle
        mouth_inner = Line(d, e)
        mouth_face = Line(e, f)
        mouth_outer = Line(f, g)
        top = Arc(center=o, start=g, end=h)  # top of the handle
        ear_outer = Line(h, a)

        axis = Line((0, -cup_depth), (0, 30), construction=true)
        Vertical(axis)
        Coincident(o, axis)
        Horizontal(ear_face)
        Horizontal(mouth_face)
        Equal(ear_face, mouth_face)
        Symmetric(a, f, axis)
        c.y == d.y  # with the arc's center on the axis, c and d mirror each other
        g.y == h.y  # (Symmetric would say the arc's center is on the axis a second time)
    }

    # speaker grille in the earpiece cup: a row of small holes made by a loop
    hole grille {
        for i in range(4) {
            dot = Circle(center=(-half + face / 2 + (i - 1.5) * 8 mm, -cup_depth + 17), radius=2.2)
        }
    }

    # microphone port in the mouthpiece cup
    hole mic {
        port = Circle(center=(half - face / 2, -cup_depth + 17), radius=4.5)
    }

    # engraved rims where the caps screw onto the cups
    drawing caps {
        ear_rim = Line((-half + rim_out, -cup_depth + rim), (-half + face - rim_in, -cup_depth + rim))
        mouth_rim = Line((half - face + rim_in, -cup_depth + rim), (half - rim_out, -cup_depth + rim))
    }

    # rims lie across the cups, `rim` above the faces
    OnLine(caps.ear_rim.start, body.ear_outer)
    OnLine(caps.ear_rim.end, body.ear_inner)
    OnLine(caps.mouth_rim.start, body.mouth_inner)
    OnLine(caps.mouth_rim.end, body.mouth_outer)
    VerticalDistance(body.a, caps.ear_rim.start, rim)
    VerticalDistance(body.f, caps.mouth_rim.end, rim)
    Horizontal(caps.ear_rim)
    Horizontal(caps.mouth_rim)
    # grille and port centered over their faces
    grille.bb.center_x == body.ear_face.midpoint.x
    grille.bb.center_y == body.a.y + 17
    mic.port.center.x == body.mouth_face.midpoint.x
    mic.port.center.y == body.f.y + 17
}
