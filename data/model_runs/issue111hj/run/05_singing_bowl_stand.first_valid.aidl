# Request (music): a stand for a 150 mm Tibetan singing bowl whose rounded bottom is close
# to a sphere of 100 mm radius, in 6 mm walnut ply, glued.
# - base: a ring 170 mm outside, 90 mm inside; three mortises 120 deg apart (one at the
#   back, 90 deg), radial, 25 mm long, 0.2 mm clearance, centred at 67.5 mm radius;
#   "SINGING BOWL" engraved along the ring's front (bottom), 7 mm sans capitals, filled,
#   reading left to right, their middle on the ring's middle radius (65 mm).
# - three fins standing radially in the mortises, each 35 mm long (from 50 to 85 mm
#   radius), a 25 mm tenon 6 mm deep under the middle; the top edge an arc cut to the
#   bowl's 100 mm radius: 20 mm high at the inner end, 53.92 mm at the outer end,
#   32.82 mm at the middle (so the bowl's lowest point floats 13.4 mm over the base).
import "std/joints.aidl"

thickness 6 mm

R_IN = 50 mm      # fin inner end, from the stand's axis
R_OUT = 85 mm
R_MID = 67.5 mm

def fin() -> solid {
    bottom = Line((50, -6), (85, -6))
    outer = Line((85, -6), (85, 53.92))
    top = Arc(start=(85, 53.92), through=(67.5, 32.82), end=(50, 20))
    inner = Line((50, 20), (50, -6))
    tenon = tab_and_slot(part="tab", length=35 mm, thickness=6 mm, tabs=1, tab=25 mm,
                         screw=0, rotation=180 deg, cx=67.5 mm, cy=-6 mm)
}

assembly stand {
    solid base {
        ring = Circle(center=(0, 0), diameter=170)
        hole bore {
            c = Circle(center=(0, 0), diameter=90)
        }
        for k in range(3) {
            m = tab_and_slot(part="slot", length=35 mm, thickness=6 mm, tabs=1, tab=25 mm,
                             screw=0, clearance=0.2 mm, rotation=90 deg + k * 120 deg,
                             cx=R_MID * cos(90 deg + k * 120 deg),
                             cy=R_MID * sin(90 deg + k * 120 deg))
        }
        drawing words {
            mid = Circle(center=(0, 0), radius=65, construction=true)
            t = Text("SINGING BOWL", along=mid, size=7, valign="middle", flip=true,
                     font="sans", fill=true)
        }
    }

    for k in range(3) {
        f = fin()
        f.bb.center == (150 + k * 50 mm, 0)
        # assembled: standing radially on the base, its plane centred on the radius
        Place(f, on=base, rotation=(90 deg, 0, 90 deg + k * 120 deg),
              position=(-3 mm * sin(90 deg + k * 120 deg), 3 mm * cos(90 deg + k * 120 deg), 6))
    }

    assert len(f) == 3, "three fins"
    assert base.ring.diameter == 170 mm and base.bore.c.diameter == 90 mm, "ring 170 / 90"
    assert distance(base.m[1].slot[0].center, base.ring.center) == 67.5 mm, "mortises at 67.5"
    assert base.m[0].slot[0].bb.height == 25 mm + 0.2 mm, "mortise 25 long plus clearance"
    assert f[0].inner.start.y - f[0].bottom.start.y == 26 mm, "20 high over the 6 mm tenon line"
    assert f[0].outer.end.y - f[0].bottom.start.y == 53.92 mm + 6 mm, "53.92 at the outer end"
    assert f[0].bottom.length == 35 mm, "fins 35 long"
    # the arc is the bowl's: radius 100 mm
    assert abs(f[0].top.radius - 100 mm) < 0.1 mm, "top edge on the bowl's 100 mm radius"
    # the words sit on the ring, clear of the mortises
    for k in range(3) {
        assert distance(base.words, base.m[k]) >= 3 mm, "words clear of the mortises"
    }
}
