# Request: a sliding bevel (T-bevel) for marking angles, cut from 6 mm birch ply.
# The stock is three layers glued: two cheeks 150 x 24 mm (R4 corners) and a spacer
# 100 x 24 mm flush with the cheeks' back end, which leaves a 50 mm long, 6 mm wide
# gap at the front for the blade. An M6 bolt (medium clearance hole, 6.6 mm) passes
# through both cheeks 12 mm from the front end, on the centre line; a wing nut clamps
# the blade. A 10 mm hanging hole goes through all three layers 12 mm from the back end.
# The blade is 200 x 20 mm, its pivot end rounded R10, with a 6.6 mm slot 120 mm long
# (tip to tip) on its centre line starting 12 mm from the rounded end, so the blade
# slides and turns on the bolt. Ticks are engraved every 10 mm along the blade's
# bottom edge, measured from its square end (3 mm long, 5 mm at every 50 mm). The outer
# cheek has "J. HOLT" engraved, filled, serif, 8 mm capitals, centred between the holes.

units mm
thickness 6 mm
import "std/fasteners.aidl"
import "std/shapes.aidl"

def cheek(engrave=false) -> solid {
    body = RoundedRectangle(center=(-63, 0), width=150, height=24, corner_radius=4)
    bolt = clearance_hole(size=6)
    HorizontalDistance(bolt.c.center, body.right.midpoint, 12)
    AlignCenterY(bolt, body)
    hole hang {
        c = Circle(center=(-126, 0), diameter=10)
    }
    HorizontalDistance(body.left.midpoint, hang.c.center, 12)
    AlignCenterY(hang, body)
    if engrave {
        drawing name {
            t = Text("J. HOLT", position=(-63, 0), size=8, font="serif", valign="middle",
                     fill=true)
        }
        name.t.position.x == (bolt.c.center.x + hang.c.center.x) / 2
        name.t.position.y == body.center.y
    }
    Rigid(self)
}

assembly bevel {
    cheek_out = cheek(engrave=true)
    cheek_in = cheek()

    solid spacer {
        body = RoundedRectangle(center=(-88, 0), width=100, height=24,
                                corner_radii=[4, 0, 0, 4])
        hole hang {
            c = Circle(center=(-126, 0), diameter=10)
        }
        HorizontalDistance(body.left.midpoint, hang.c.center, 12)
        AlignCenterY(hang, body)
        Rigid(self)
    }

    solid blade {
        body = RoundedRectangle(center=(84.7, 0), width=200, height=20,
                                corner_radii=[10, 0, 0, 10])
        s = slot_hole(length=120, width=6.6)
        s.bb.left == body.bb.left + 12
        AlignCenterY(s, body)
        drawing ticks {
            for k in range(1, 19) {
                t = Line((184.7 - 10 * k, -10), (184.7 - 10 * k, -10 + (5 if k % 5 == 0 else 3)))
            }
        }
        Rigid(self)
    }

    # flat on the sheet: one under the other
    Below(cheek_in, cheek_out, gap=5)
    AlignLeft(cheek_in, cheek_out)
    Below(spacer, cheek_in, gap=5)
    AlignLeft(spacer, cheek_in)
    Below(blade, spacer, gap=5)
    AlignLeft(blade, spacer)

    # assembled: the bolt on the z axis, the blade swung out 40 degrees
    Place(cheek_in, position=(0, 0, 0), rotation=(0, 0, 0))
    Place(spacer, position=(0, 0, 6), rotation=(0, 0, 0))
    Place(blade, position=(0, 0, 6), rotation=(0, 0, 40 deg))
    Place(cheek_out, position=(0, 0, 12), rotation=(0, 0, 0))

    # the request's numbers
    assert cheek_in.body.bb.width == 150 mm and cheek_in.body.bb.height == 24 mm, "cheek 150 x 24"
    assert cheek_in.bolt.c.diameter == 6.6 mm, "M6 medium clearance is 6.6 mm"
    assert cheek_in.body.bb.right - cheek_in.bolt.c.center.x == 12 mm, "bolt 12 from the front"
    assert cheek_in.hang.c.center.x - cheek_in.body.bb.left == 12 mm, "hanging hole 12 from the back"
    assert cheek_in.hang.c.diameter == 10 mm, "10 mm hanging hole"
    assert spacer.body.bb.width == 100 mm and spacer.body.bb.height == 24 mm, "spacer 100 x 24"
    assert cheek_in.body.bb.width - spacer.body.bb.width == 50 mm, "50 mm blade gap"
    assert spacer.hang.c.center.x - spacer.body.bb.left == 12 mm, "spacer's hanging hole matches"
    assert blade.body.bb.width == 200 mm and blade.body.bb.height == 20 mm, "blade 200 x 20"
    assert blade.s.bb.width == 120 mm and blade.s.bb.height == 6.6 mm, "slot 120 x 6.6"
    assert blade.s.bb.left - blade.body.bb.left == 12 mm, "slot 12 from the rounded end"
    assert len(blade.ticks.t) == 18, "ticks every 10 mm up to 180"
    assert blade.body.bb.right - blade.ticks.t[0].start.x == 10 mm, "first tick 10 mm from the square end"
    assert distance(cheek_out.name, cheek_out.bolt) >= 3 mm, "name clear of the bolt hole"
    assert distance(cheek_out.name, cheek_out.hang) >= 3 mm, "name clear of the hanging hole"
}
