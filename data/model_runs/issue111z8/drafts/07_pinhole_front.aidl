# Science: the front panel of a pinhole camera, 3 mm plywood, with its swinging
# shutter. Panel 100 x 100 mm, 5 mm corner radius; a 20 mm aperture in its
# centre (the pinhole foil is taped behind it); a 3.4 mm pivot hole 30 mm right
# of the aperture's centre; four M3 holes 3.4 mm countersunk for 6.5 mm flat
# heads, 8 mm in from each side at the corners; "PINHOLE f/150" engraved 5 mm
# tall, its baseline 10 mm above the bottom edge.
# Shutter (separate part): the hull of a 30 mm disc that covers the aperture and
# a 12 mm disc at the pivot, their centres 30 mm apart, with a 3.4 mm pivot hole.

units mm
thickness 3 mm

pivot = 30 mm

assembly camera {
    solid panel {
        body = RoundedRectangle(center=(0, 0), width=100, height=100, corner_radius=5)
        Fixed(body)
        hole aperture {
            c = Circle(center=(0, 0), diameter=20)
        }
        hole pin {
            c = Circle(center=(pivot, 0), diameter=3.4)
        }
        hole screw {
            c = Circle(center=(-42, -42), diameter=3.4)
        }
        screws = CornerPattern(screw, body, inset=8)
        Countersink(screws, diameter=6.5)
        drawing label {
            t = Text("PINHOLE f/150", position=(0, -50 + 10), size=5)
        }
    }

    solid shutter {
        blade = Hull(Circle(center=(0, 0), diameter=30), Circle(center=(pivot, 0), diameter=12))
        hole pin {
            c = Circle(center=(pivot, 0), diameter=3.4)
        }
    }
    RightOf(shutter, panel, gap=8)
    AlignCenterY(shutter, panel)

    assert panel.body.width == 100 mm and panel.body.height == 100 mm, "panel 100 x 100"
    assert panel.aperture.c.diameter == 20 mm, "aperture 20"
    assert panel.aperture.c.center == panel.body.center, "aperture centred"
    assert panel.pin.c.center.x - panel.aperture.c.center.x == 30 mm, "pivot 30 right of the aperture"
    assert len(panel.screws) == 4, "four screws"
    assert panel.screws[0].c.center.x - panel.body.bb.left == 8 mm, "screws 8 in"
    assert panel.screws[0].c.center.y - panel.body.bb.bottom == 8 mm, "screws 8 up"
    assert panel.label.t.position.y - panel.body.bb.bottom == 10 mm, "label 10 above the bottom"
    assert shutter.pin.c.center.x - shutter.bb.left == 15 mm + 30 mm, "shutter: pivot 30 from the disc's centre"
    assert shutter.bb.height == 30 mm, "shutter disc 30"
}
