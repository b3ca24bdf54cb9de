# Gear with a hub: a 30-tooth spur gear, module 2 mm (60 mm pitch diameter), 8 mm bore,
# four 8 mm lightening holes on a 34 mm circle; plus a separate hub disc 24 mm across
# with the same 8 mm bore and two 3.2 mm screw holes 16 mm apart that line up with two
# 3.2 mm holes in the gear (glued/screwed to the gear face). Two parts: an assembly.
import "std/gears.aidl"

thickness 3 mm

assembly gear_with_hub {
    solid gear {
        g = spur_gear(teeth=30, module=2 mm, bore=8 mm)
        hole lighten {
            c = Circle(center=(17, 0), diameter=8)
        }
        Coincident(lighten.c.center, polar(g.hub.center, 17, 45 deg))
        CircularPattern(lighten, 4, g.hub.center)
        hole screw {
            a = Circle(center=(0, 8), diameter=3.2)
            b = Circle(center=(0, -8), diameter=3.2)
        }
        At(screw.a.center, g.hub.center, dy=8)
        At(screw.b.center, g.hub.center, dy=-8)
    }

    solid hub {
        disc = Circle(center=(50, 0), diameter=24)
        hole bore {
            c = Circle(center=(50, 0), diameter=8)
        }
        hole screw {
            a = Circle(center=(50, 8), diameter=3.2)
            b = Circle(center=(50, -8), diameter=3.2)
        }
        Concentric(bore.c, disc)
        At(screw.a.center, disc.center, dy=8)
        At(screw.b.center, disc.center, dy=-8)
    }
    RightOf(hub, gear, gap=5)
    AlignCenterY(hub, gear)
}
