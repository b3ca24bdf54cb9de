# Request (kitchen): "An under-cupboard rack for Nespresso OriginalLine capsules (body 30 mm,
# rim 37 mm). Three 3 mm ply plates, each 212 x 220 mm, stacked and screwed under the shelf:
# the bottom plate has four channels 30.5 mm wide, the spacer four channels 38.5 mm wide for
# the rims, both 200 mm deep from the front edge, open at the front with 2 mm chamfers to lead
# the capsules in, round at the back, 48 mm apart; the top plate is plain. Four 4.5 mm screw
# holes through all three, 7.5 mm in from the sides and 10 mm from front and back, countersunk
# 8 mm on the bottom plate (the screw heads are underneath). Each channel holds 5 capsules."

thickness 3 mm

param pitch = 48 mm, min = 42 mm, max = 60 mm
param depth = 220 mm, min = 120 mm, max = 300 mm
param run = 200 mm, min = 100 mm, max = 280 mm

rows = 4
plate_w = 212 mm
body_d = 30.5 mm
rim_d = 38.5 mm
capsule_rim = 37 mm

def rack_plate(w=212 mm, d=220 mm, ch=0 mm, run=200 mm, pitch=48 mm, n=4, sink=false) -> solid {
    body = Rectangle(center=(0, 0), width=w, height=d)
    if ch > 0 mm {
        # one channel from 1 mm past the front edge, `run` deep, round at the back
        hole channel {
            c = RoundedRectangle(center=(-(n - 1) / 2 * pitch, -d / 2 + (run - 1 mm) / 2),
                                 width=ch, height=run + 1 mm,
                                 corner_radii=[ch / 2, ch / 2, 0, 0])
        }
        channels = LinearPattern(channel, n, (pitch, 0))
    }
    # FIX after the first valid program: the chamfer stood inside the `if`, so the plain top
    # plate kept square corners over the chamfered ones of the other two (a ragged stack)
    Chamfer(2)
    hole screw { c = Circle(center=(0, 0), diameter=4.5) }
    screws = CornerPattern(screw, body, inset=(7.5, 10))
    if sink {
        Countersink(screw, diameter=8)
    }
}

assembly pod_rack {
    bottom = rack_plate(w=plate_w, d=depth, ch=body_d, run=run, pitch=pitch, n=rows, sink=true)
    spacer = rack_plate(w=plate_w, d=depth, ch=rim_d, run=run, pitch=pitch, n=rows)
    top = rack_plate(w=plate_w, d=depth, run=run, pitch=pitch, n=rows)

    # on the sheet: side by side, 5 mm apart
    RightOf(spacer, bottom, gap=5)
    RightOf(top, spacer, gap=5)
    AlignCenterY(spacer.body, bottom.body)
    AlignCenterY(top.body, spacer.body)

    # assembled: stacked, the bottom plate lowest
    Place(bottom, position=(0, 0, 0))
    Place(spacer, position=(0, 0, 3))
    Place(top, position=(0, 0, 6))

    # the request's numbers
    assert bottom.body.width == 212 mm and bottom.body.height == 220 mm, "212 x 220 plates"
    assert len(bottom.channels) == 4 and len(spacer.channels) == 4, "four channels"
    assert bottom.channels[1].c.center.x - bottom.channels[0].c.center.x == 48 mm, "48 mm apart"
    assert bottom.channels[0].c.width == 30.5 mm, "body channel 30.5 mm"
    assert spacer.channels[0].c.width == 38.5 mm, "rim channel 38.5 mm"
    assert bottom.channels[0].c.bb.top - bottom.body.bb.bottom == 200 mm, "200 mm deep"
    assert spacer.channels[3].c.bb.top - spacer.body.bb.bottom == 200 mm, "200 mm deep"
    assert floor(200 mm / capsule_rim) == 5, "5 capsules a channel"
    assert bottom.screws[0].c.center.x - bottom.body.bb.left == 7.5 mm, "7.5 mm from the side"
    assert bottom.screws[0].c.center.y - bottom.body.bb.bottom == 10 mm, "10 mm from the front"
    assert bottom.body.bb.top - bottom.screws[2].c.center.y == 10 mm, "10 mm from the back"
    # the screws stay in the side rails of the spacer, clear of the rim channels
    assert spacer.screws[0].c.bb.right < spacer.channels[0].c.bb.left - 2 mm, "side rail wall"
}
