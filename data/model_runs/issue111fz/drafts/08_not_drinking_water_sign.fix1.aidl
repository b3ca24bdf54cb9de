# Request (signs): a "NOT DRINKING WATER" sign (the ISO 7010 P005 kind) for the tap in my
# workshop yard, in two layers:
# - a plate of 5 mm white acrylic, 200 x 260 mm, corners R8, four M4 countersunk screw holes
#   (4.5 mm, 8 mm heads) 12 mm in from each corner; on it, engraved filled and later
#   paint-filled black, a tap over a glass: the tap's wall flange, its pipe running right and
#   bending down into a spout, a handle on top, a drop under the spout and a tapered glass
#   under the drop; the pictogram kept 2 mm clear of the red bar and 3 mm inside the red ring;
#   "NOT DRINKING" and "WATER" engraved filled, bold sans 16 mm, under the symbol;
# - a red 3 mm acrylic prohibition symbol glued on: a ring 160 mm across, 128 mm inside
#   (0.8 of it), and a bar 12.8 mm wide (0.08 of it) from upper left to lower right at 45 deg,
#   its centre 30 mm above the plate's centre.

thickness 5 mm

D = 160 mm
cy = 30 mm                       # the symbol's centre above the plate's centre
bar_w = 0.08 * D
inner_r = 0.8 * D / 2

assembly sign {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=200 mm, height=260 mm, corner_radius=8 mm)
        Fixed(body)
        hole screw { c = Circle(center=(0, 0), diameter=4.5 mm) }
        screws = CornerPattern(screw, body, inset=12 mm)
        Countersink(screws, diameter=8 mm)

        drawing picto {
            # FIX after the first valid program: there the clip band (the bar plus 2 mm each
            # side) left the flange and the drop as slivers and cut the pipe's end and a corner
            # of the glass. Now the whole tap and the drop lie above the band and the band
            # crosses the glass through its middle, leaving two solid halves.
            flange = Rectangle(center=(-12, cy + 38), width=6, height=16, fill=true)
            pipe = Stroke(Polyline([(-12, cy + 38), (20, cy + 38), (28, cy + 30), (28, cy + 24)]),
                          width=10, cap="flat", fill=true)
            stem = Rectangle(center=(4, cy + 48), width=5, height=10, fill=true)
            handle = Rectangle(center=(4, cy + 55), width=22, height=5, fill=true)
            drop = Hull(Circle(center=(28, cy + 14), radius=3.5), Point(28, cy + 21), fill=true)
            glass = Trapezoid(center=(22, cy - 22), bottom_width=26, top_width=34, height=36,
                              fill=true)
            ring_ref = Circle(center=(0, cy), radius=inner_r, construction=true)
            hole clip {
                band = Rectangle(center=(0, cy), width=D, height=bar_w + 4 mm, rotation=-45 deg)
            }
        }

        drawing words {
            line1 = Text("NOT DRINKING", position=(0, -72), size=16, font="sans:Bold",
                         valign="middle", max_width=176 mm, fill=true)
            line2 = Text("WATER", position=(0, -100), size=16, font="sans:Bold",
                         valign="middle", fill=true)
        }
    }

    solid symbol {
        thickness 3 mm
        solid ring {
            outer = Circle(center=(0, cy), diameter=D)
            Fixed(outer)
            hole inside { c = Circle(center=(0, cy), radius=inner_r) }
        }
        bar = Rectangle(center=(0, cy), width=2 * inner_r + 8 mm, height=bar_w,
                        rotation=-45 deg)
        Fixed(bar)
    }

    # flat on the sheet
    RightOf(symbol, plate, gap=10)
    AlignTop(symbol, plate)

    # in 3D: the symbol glued on the plate
    Place(plate, position=(0, 0, 0))
    Place(symbol, position=(0, 0, 5 mm))

    # the request's numbers
    assert plate.body.bb.width == 200 mm and plate.body.bb.height == 260 mm, "plate 200 x 260"
    assert len(plate.screws) == 4, "four screws"
    assert plate.screws[0].c.center.x - plate.body.bb.left == 12 mm and
        plate.screws[0].c.center.y - plate.body.bb.bottom == 12 mm, "12 mm in from the corner"
    assert symbol.ring.outer.diameter == 160 mm, "ring 160"
    assert symbol.ring.inside.c.diameter == 128 mm, "128 inside"
    assert symbol.bar.height == 12.8 mm, "bar 12.8 wide"
    assert symbol.ring.outer.center.y - plate.body.center.y == 30 mm, "symbol 30 mm up"
    assert plate.picto.clip.band.height - symbol.bar.height == 4 mm, "2 mm clear of the bar"
    assert distance(plate.picto.flange, plate.picto.ring_ref) >= 3 mm and
        distance(plate.picto.handle, plate.picto.ring_ref) >= 3 mm and
        distance(plate.picto.glass, plate.picto.ring_ref) >= 3 mm, "3 mm inside the ring"
    assert distance(plate.picto.flange, plate.picto.clip.band) >= 2 mm and
        distance(plate.picto.pipe, plate.picto.clip.band) >= 2 mm and
        distance(plate.picto.drop, plate.picto.clip.band) >= 2 mm, "the tap clear of the bar"
    assert plate.words.line1.bb.top <= cy - D / 2 - 6 mm, "words under the symbol"
    assert distance(plate.words, plate.screws[0]) >= 4 mm and
        distance(plate.words, plate.screws[1]) >= 4 mm, "words clear of the screws"
}
