# Request: a white-light solar filter cell for my 80 mm refractor, whose dew shield is 92 mm
# across outside; cut from 3 mm plywood, five rings 120 mm across, bolted together with six
# M3 screws on a 108 mm bolt circle (3.4 mm holes, the first at 30 degrees):
# - a front ring and a seat ring with an 84 mm aperture: the solar film is clamped between them;
# - three sleeve rings with a 92.8 mm bore (the dew shield plus 0.8 mm for felt tape), glued
#   into a 9 mm deep sleeve that slips over the dew shield;
# - engraved on the front ring, in 4 mm letters round the aperture, reading the right way up:
#   "SOLAR FILTER" over the top and "CHECK FILM BEFORE EVERY USE" under the bottom, clear of
#   the aperture and the screw holes.

import "std/shapes.aidl"

units mm
thickness 3 mm

param shield_d = 92 mm, min = 60 mm, max = 110 mm

def ring(inner_d=84 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=120)
    hole bore { c = Circle(center=(0, 0), diameter=inner_d) }
    bolts = bolt_circle(count=6, pcd=108 mm, hole_d=3.4 mm, start=30 deg)
}

assembly filter_cell {
    front = ring(inner_d=84 mm)
    seat = ring(inner_d=84 mm)
    sleeve1 = ring(inner_d=shield_d + 0.8 mm)
    sleeve2 = ring(inner_d=shield_d + 0.8 mm)
    sleeve3 = ring(inner_d=shield_d + 0.8 mm)

    drawing warning {
        over_path = Circle(center=(0, 0), radius=45, construction=true)
        over = Text("SOLAR FILTER", along=over_path, size=4)
        under_path = Circle(center=(0, 0), radius=49, construction=true)
        under = Text("CHECK FILM BEFORE EVERY USE", along=under_path, size=4, flip=true)
    }
    Concentric(warning.over_path, front.disc)
    CutInto(warning, front)

    RightOf(seat, front, gap=5)
    AlignTop(seat, front)
    RightOf(sleeve1, seat, gap=5)
    AlignTop(sleeve1, seat)
    RightOf(sleeve2, sleeve1, gap=5)
    AlignTop(sleeve2, sleeve1)
    RightOf(sleeve3, sleeve2, gap=5)
    AlignTop(sleeve3, sleeve2)

    assert front.disc.diameter == 120 mm, "rings 120 mm across"
    assert front.bore.c.diameter == 84 mm and seat.bore.c.diameter == 84 mm, "84 mm aperture"
    assert sleeve1.bore.c.diameter == 92 mm + 0.8 mm, "bore: dew shield + 0.8 mm"
    assert front.bolts.count == 6 and front.bolts.pcd == 108 mm, "six screws on 108 mm"
    assert front.bolts.hole_d == 3.4 mm, "M3 clearance"
    assert distance(warning, front.bore) >= 1 mm, "text clear of the aperture"
    assert distance(warning, front.bolts) >= 1 mm, "text clear of the screw holes"
}
