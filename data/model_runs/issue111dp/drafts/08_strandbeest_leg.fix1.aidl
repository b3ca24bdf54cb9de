# Request (science): a working model of one leg of Theo Jansen's Strandbeest for a science
# club, 4 mm ply, at twice Jansen's "holy numbers" (a 38, b 41.5, c 39.3, d 40.1, e 55.8,
# f 39.4, g 36.7, h 65.7, i 49, j 50, k 61.9, l 7.8, m 15 -- all x 2 mm), joints on M4 bolts
# (4.2 mm holes). Parts: an upright frame 300 x 290 mm (R10) with the crank axle O and the
# fixed pivot A (76 mm left of O, 15.6 mm below it), standing by three 30 mm tabs in a base
# 320 x 100 mm (R10); a crank disc 80 mm across with the crank pin 30 mm out and a 12 mm
# finger hole opposite; four bars 14 mm wide with round ends (j 100, k 123.8, c 78.6,
# f 78.8 mm between holes), each engraved with its letter; two triangular plates with
# rounded corners (R8) and a lightening window 14 mm in from the edges: the upper b-d-e
# (83, 80.2, 111.6 mm) and the foot g-h-i (73.4, 131.4, 98 mm). Engraved on the frame,
# behind the leg: the leg drawn at crank angle 0 and the closed path of the foot through
# its twelve positions at every 30 degrees of the crank, solved from the bar lengths;
# and "JANSEN LINKAGE 2:1". The foot must clear the base by at least 10 mm.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
m = 30 mm
a = 76 mm
l = 15.6 mm
b = 83 mm
c = 78.6 mm
d = 80.2 mm
e = 111.6 mm
f = 78.8 mm
g = 73.4 mm
h = 131.4 mm
i = 98 mm
j = 100 mm
k = 123.8 mm
pin = 4.2 mm
frame_cx = -90 mm
# FIX after the first valid program: the foot plate's R8 corner came 8.3 mm over the base
# (my assert measured the foot's pivot, 16.3 mm); the frame now sits 10 mm lower on the
# axles (same 300 x 290 size), and the assert measures the plate's edge
frame_bottom = -210 mm
frame_top = 80 mm

# starting guesses (to 10 mm) for B, C, D, E, F at crank angles 0, 30, ... 330 deg
gB = [(-50, 60), (-60, 70), (-80, 70), (-90, 70), (-110, 60), (-120, 60), (-110, 60),
      (-80, 70), (-60, 70), (-40, 60), (-40, 60), (-40, 60)]
gC = [(-50, -90), (-40, -90), (-40, -90), (-40, -90), (-50, -90), (-90, -90), (-130, -70),
      (-140, -60), (-130, -70), (-110, -90), (-90, -90), (-70, -90)]
gD = [(-150, 20), (-150, 0), (-160, -10), (-160, -30), (-150, -40), (-150, -50), (-150, -40),
      (-160, -20), (-150, 10), (-150, 20), (-150, 30), (-150, 20)]
gE = [(-120, -60), (-110, -60), (-110, -80), (-110, -100), (-120, -120), (-150, -130),
      (-190, -110), (-210, -70), (-200, -50), (-180, -50), (-150, -50), (-130, -50)]
gF = [(-90, -180), (-60, -180), (-40, -180), (-20, -180), (-10, -180), (-20, -170),
      (-70, -150), (-110, -150), (-140, -170), (-140, -180), (-130, -180), (-110, -180)]

# poses at crank angle 0 for the assembled view (worked out beforehand, degrees)
th_xb = 141.29
th_xc = -132.67
th_ac = -73.67
th_de = -66.73
th_ab = 70.3
th_ce = 151.59

def bar(L=100 mm, name="j") -> solid {
    body = Slot(start=(0, 0), end=(L, 0), width=14)
    hole ends {
        h0 = Circle(center=(0, 0), diameter=pin)
        h1 = Circle(center=(L, 0), diameter=pin)
    }
    drawing letter { n = Text(name, position=(L / 2, 0), size=6, valign="middle") }
    Fixed(body)
    Fixed(ends)
    assert ends.h1.center.x - ends.h0.center.x == L
}

# a triangular plate: v0 at (0, 0), v1 at (p, 0), v2 above; p = |v0 v1|, q = |v0 v2|, r = |v1 v2|
def plate3(p=83 mm, q=80.2 mm, r=111.6 mm) -> solid {
    x2 = (p ** 2 + q ** 2 - r ** 2) / (2 * p)
    y2 = sqrt(q ** 2 - x2 ** 2)
    body = Hull(Circle(center=(0, 0), radius=8), Circle(center=(p, 0), radius=8),
                Circle(center=(x2, y2), radius=8))
    hole pivots {
        h0 = Circle(center=(0, 0), diameter=pin)
        h1 = Circle(center=(p, 0), diameter=pin)
        h2 = Circle(center=(x2, y2), diameter=pin)
    }
    hole window {
        w = Inset(Polygon([(0, 0), (p, 0), (x2, y2)]), 14 mm)
        Fillet(3 mm)
    }
    Fixed(pivots)
    assert abs(distance(pivots.h0.center, pivots.h2.center) - q) < 0.01 mm
    assert abs(distance(pivots.h1.center, pivots.h2.center) - r) < 0.01 mm
}

assembly leg {
    solid frame {
        board = RoundedRectangle(center=(frame_cx, (frame_bottom + frame_top) / 2), width=300,
                                 height=frame_top - frame_bottom, corner_radius=10)
        strip = Rectangle(center=(frame_cx, frame_bottom - t / 2), width=300, height=t)
        feet = tab_and_slot(part="tab", length=300 mm, thickness=t, tabs=3, tab=30 mm, screw=0,
                            rotation=180 deg, cx=frame_cx, cy=frame_bottom - t)
        hole axles {
            o = Circle(center=(0, 0), diameter=pin)
            pa = Circle(center=(-a, -l), diameter=pin)
        }
        drawing figure {
            fa = Point(-a, -l)
            Fixed(fa)
            for n in range(12) {
                px = Point(m * cos(n * 30 deg), m * sin(n * 30 deg))
                Fixed(px)
                pb = Point(gB[n])
                pc = Point(gC[n])
                pd = Point(gD[n])
                pe = Point(gE[n])
                pf = Point(gF[n])
                Distance(pb, fa, b)
                Distance(pb, px, j)
                Distance(pc, fa, c)
                Distance(pc, px, k)
                Distance(pd, fa, d)
                Distance(pd, pb, e)
                Distance(pe, pd, f)
                Distance(pe, pc, g)
                Distance(pf, pe, h)
                Distance(pf, pc, i)
            }
            path = Spline([pf[n] for n in range(12)], closed=true)
            crank0 = Line(Point(0, 0), px[0])
            lj = Line(px[0], pb[0])
            lk = Line(px[0], pc[0])
            lb = Line(fa, pb[0])
            lc = Line(fa, pc[0])
            ld = Line(fa, pd[0])
            le = Line(pb[0], pd[0])
            lf = Line(pd[0], pe[0])
            lg = Line(pc[0], pe[0])
            lh = Line(pe[0], pf[0])
            li = Line(pc[0], pf[0])
            title = Text("JANSEN LINKAGE 2:1", position=(frame_cx - 140 mm, frame_top - 15 mm), size=8,
                         anchor="start")
        }
        Fixed(board)
        Fixed(strip)
        assert board.bb.width == 300 mm and board.bb.height == 290 mm
        assert abs(axles.pa.center.x - axles.o.center.x + 76 mm) < 0.01 mm and
            abs(axles.pa.center.y - axles.o.center.y + 15.6 mm) < 0.01 mm
        assert min([figure.pf[n].y for n in range(12)]) - 8 mm - frame_bottom >= 10 mm, "foot clears the base"
        # FIX after the first valid program: the leg's lines end on the pivots by design (W0505)
        AllowOverlap(figure.crank0, figure.lb, figure.lc, figure.ld, self)
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=320, height=100, corner_radius=10)
        slots = tab_and_slot(part="slot", length=300 mm, thickness=t, tabs=3, tab=30 mm,
                             screw=0, cx=0, cy=38 mm)
        Fixed(plate)
    }

    solid crank {
        disc = Circle(center=(0, 0), diameter=80)
        hole holes {
            axle = Circle(center=(0, 0), diameter=pin)
            crankpin = Circle(center=(m, 0), diameter=pin)
            finger = Circle(center=(-24 mm, 0), diameter=12)
        }
        Fixed(disc)
        Fixed(holes)
        assert holes.crankpin.center.x - holes.axle.center.x == 30 mm
    }

    bar_j = bar(L=j, name="j")
    bar_k = bar(L=k, name="k")
    bar_c = bar(L=c, name="c")
    bar_f = bar(L=f, name="f")
    upper = plate3(p=b, q=d, r=e)
    foot = plate3(p=g, q=i, r=h)

    assert bar_j.L == 100 mm and bar_k.L == 123.8 mm and bar_c.L == 78.6 mm and bar_f.L == 78.8 mm
    assert upper.p == 83 mm and upper.q == 80.2 mm and upper.r == 111.6 mm
    assert foot.p == 73.4 mm and foot.q == 98 mm and foot.r == 131.4 mm

    # flat on the sheet
    Below(base, frame, gap=6)
    AlignLeft(base, frame)
    RightOf(crank, frame, gap=6)
    AlignTop(crank, frame)
    Below(bar_j, crank, gap=6)
    AlignLeft(bar_j, crank)
    Below(bar_k, bar_j, gap=6)
    AlignLeft(bar_k, crank)
    Below(bar_c, bar_k, gap=6)
    AlignLeft(bar_c, crank)
    Below(bar_f, bar_c, gap=6)
    AlignLeft(bar_f, crank)
    Below(upper, bar_f, gap=6)
    AlignLeft(upper, crank)
    RightOf(foot, upper, gap=6)
    AlignTop(foot, upper)

    # assembled at crank angle 0: the frame's front face at y = -4, the leg in layers before it
    Place(frame, position=(0, 0, 0), face="front", up="up")
    Place(base, position=(frame_cx, -t / 2 - 38 mm, frame_bottom - t), face="up", up="back")
    Place(crank, position=(0, -t, 0), face="front", up="up")
    Place(upper, position=(-a, -t, -l), face="front", up=(-sin(th_ab * 1 deg), 0, cos(th_ab * 1 deg)))
    Place(bar_j, position=(m, -2 * t, 0), face="front", up=(-sin(th_xb * 1 deg), 0, cos(th_xb * 1 deg)))
    Place(bar_c, position=(-a, -2 * t, -l), face="front", up=(-sin(th_ac * 1 deg), 0, cos(th_ac * 1 deg)))
    Place(bar_f, position=(-149.59 mm, -2 * t, 16.29 mm), face="front",
          up=(-sin(th_de * 1 deg), 0, cos(th_de * 1 deg)))
    Place(foot, position=(-53.9 mm, -3 * t, -91.03 mm), face="front",
          up=(-sin(th_ce * 1 deg), 0, cos(th_ce * 1 deg)))
    Place(bar_k, position=(m, -4 * t, 0), face="front", up=(-sin(th_xc * 1 deg), 0, cos(th_xc * 1 deg)))
}
