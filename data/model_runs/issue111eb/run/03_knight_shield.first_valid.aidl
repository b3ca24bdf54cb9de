# Request: a child's knight shield, 6 mm poplar ply, 300 mm wide and 380 mm tall: a
# "heater" shield with a straight top (corners rounded R15), straight sides 150 mm long,
# then two arcs that meet at the bottom point (the right one centred on the line of the
# sides' lower ends beyond the left side, and its mirror; tip rounded R10). Engraved on
# the front: a border line 12 mm inside the edge, "SIR OSCAR" in bold serif 28 mm capitals
# filled, baseline 70 mm above the centre, two filled 5-point stars (R22, inner R9) at
# (-80, 140) and (80, 140) and a bigger one (R30, inner R12) at (0, -100), from the centre.
# On the back a grip 160 mm long standing 60 mm proud, top corners R10, with a 100 x 28 mm
# round-ended hand hole, glued by two 25 mm tenons through mortises (0.2 mm clearance),
# flush with the front, its middle 40 mm right of the centre on the centre line; two 30 x 4 mm
# strap slots for a 25 mm forearm strap at x = -100, 40 mm above and below the centre line.

units mm
thickness 6 mm
import "std/joints.aidl"

W = 300 mm
H = 380 mm
S = 150 mm      # straight sides
B = 12 mm       # border inset
hw = W / 2
yt = H / 2
yk = yt - S     # where the sides turn into the arcs
yb = -H / 2     # the point
c = ((yk - yb) ** 2 - hw ** 2) / (2 * hw)   # the arcs' centres lie c beyond the far side
R = hw + c
ta = acos(c / R)          # the point, seen from an arc's centre
tb = acos(c / (R - B))    # the border's point

assembly kit {
    solid shield {
        top = Line((-hw, yt), (hw, yt))
        right = Line((hw, yt), (hw, yk))
        rarc = Arc(center=(-c, yk), radius=R, start_angle=-ta, end_angle=0 deg)
        larc = Arc(center=(c, yk), radius=R, start_angle=180 deg, end_angle=180 deg + ta)
        left = Line((-hw, yk), (-hw, yt))
        Fillet(top.start, 15)
        Fillet(top.end, 15)
        Fillet(rarc.start, 10)

        mort = tab_and_slot(part="slot", length=160, thickness=6, tabs=2, tab=25, screw=0,
                            clearance=0.2, cx=40, cy=0)
        hole straps {
            s1 = Slot(center=(-100, 40), length=30, width=4)
            s2 = Slot(center=(-100, -40), length=30, width=4)
        }

        drawing border {
            bt = Line((-hw + B, yt - B), (hw - B, yt - B))
            br = Line((hw - B, yt - B), (hw - B, yk))
            bra = Arc(center=(-c, yk), radius=R - B, start_angle=-tb, end_angle=0 deg)
            bla = Arc(center=(c, yk), radius=R - B, start_angle=180 deg, end_angle=180 deg + tb)
            bl = Line((-hw + B, yk), (-hw + B, yt - B))
        }
        drawing emblem {
            name = Text("SIR OSCAR", position=(0, 70), size=28, font="serif:Bold", fill=true)
            st1 = Star(center=(-80, 140), points=5, outer_radius=22, inner_radius=9, fill=true)
            st2 = Star(center=(80, 140), points=5, outer_radius=22, inner_radius=9, fill=true)
            st3 = Star(center=(0, -100), points=5, outer_radius=30, inner_radius=12, fill=true)
        }
    }

    solid grip {
        body = RoundedRectangle(center=(0, 33), width=160, height=66, corner_radii=[10, 10, 0, 0])
        tenons = tab_and_slot(part="tab", length=160, thickness=6, tabs=2, tab=25, screw=0,
                              rotation=180 deg, cx=0, cy=0)
        hole hand {
            h = Slot(center=(0, 36), length=100, width=28)
        }
    }

    RightOf(grip, shield, gap=10)
    AlignTop(grip, shield)

    # assembled: the shield face up (its front is the top face), the grip under it,
    # its tenons up through the mortises, flush with the front
    Place(shield, position=(0, 0, 0), rotation=(0, 0, 0))
    Place(grip, position=(40, -3, 6), rotation=(-90 deg, 0, 0))

    # the request's numbers
    assert shield.bb.width == 300 mm and shield.bb.height == 380 mm, "300 x 380"
    assert shield.right.length == 150 mm, "straight sides 150"
    assert shield.top.start.y - shield.border.bt.start.y == 12 mm, "border 12 mm in"
    assert shield.emblem.name.size == 28 mm, "28 mm capitals"
    assert shield.emblem.name.position.y - shield.right.end.y == 70 mm - (yt - S), "name 70 above the centre"
    assert shield.emblem.st3.outer_radius == 30 mm and shield.emblem.st1.outer_radius == 22 mm, "stars"
    assert grip.body.bb.width == 160 mm, "grip 160 long"
    assert grip.body.bb.top - grip.tenons.gap[0].bb.top == 60 mm, "grip 60 proud"
    assert grip.hand.h.length == 100 mm and grip.hand.h.width == 28 mm, "hand hole 100 x 28"
    assert len(shield.mort.slot) == 2 and shield.mort.slot[0].bb.width == 25.2 mm, "two 25 mm mortises, 0.2 clearance"
    assert shield.straps.s1.length == 30 mm and shield.straps.s1.width == 4 mm, "strap slots 30 x 4"
    assert shield.straps.s1.center.y - shield.straps.s2.center.y == 80 mm, "strap slots 40 above and below"
    assert distance(shield.emblem, shield.straps) >= 5 mm, "emblem clear of the strap slots"
    assert distance(shield.emblem, shield.mort) >= 5 mm, "emblem clear of the mortises"
    assert distance(shield.emblem, shield.border) >= 5 mm, "emblem inside the border"
}
