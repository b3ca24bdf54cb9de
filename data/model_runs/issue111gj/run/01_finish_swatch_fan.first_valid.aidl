# Request: a finish swatch fan for the workshop wall. Five blades of 3 mm birch ply, each a
# 150 x 40 mm stadium (round ends, R20), pinned together by an M5 Chicago screw through a
# 5.2 mm pivot hole centred in one round end (20 mm from that end). Four blades get a finish
# each and carry its name engraved (DANISH OIL, WALNUT STAIN, EBONY DYE, WHITE WAX) plus a
# number "No. 1".."No. 4" near the far end; the fifth is the cover blade engraved
# "FINISH SAMPLES" and "2026". In use the blades fan out 15 deg apart about the screw.

units mm
thickness 3 mm

finishes = ["DANISH OIL", "WALNUT STAIN", "EBONY DYE", "WHITE WAX"]

def blade(name="SAMPLE", tag="No. 1") -> solid {
    # pivot at (0, 0); the stadium runs to +x
    body = Slot(center=(55, 0), length=150, width=40)
    hole pivot {
        c = Circle(center=(0, 0), diameter=5.2)
    }
    drawing label {
        t = Text(name, position=(14, 0), size=7, anchor="start", valign="middle", max_width=80)
    }
    drawing number {
        n = Text(tag, position=(122, 0), size=5, anchor="end", valign="middle")
    }
}

assembly swatch_fan {
    for i in range(4) {
        b = blade(name=finishes[i], tag=f"No. {i + 1}")
    }
    cover = blade(name="FINISH SAMPLES", tag="2026")

    # laid out flat for cutting: a column, 5 mm apart
    for i in range(1, 4) {
        Below(b[i], b[i - 1], gap=5)
        AlignLeft(b[i], b[i - 1])
    }
    Below(cover, b[3], gap=5)
    AlignLeft(cover, b[3])

    # assembled: stacked on the screw, fanned 15 deg apart, cover on top
    for i in range(4) {
        Place(b[i], position=(0, 0, i * 3 mm), rotation=(0, 0, i * 15 deg))
    }
    Place(cover, position=(0, 0, 12 mm), rotation=(0, 0, 60 deg))

    assert len(b) == 4, "four finish blades"
    assert b[0].body.bb.width == 150 mm, "blade 150 long"
    assert b[0].body.bb.height == 40 mm, "blade 40 wide"
    assert b[0].pivot.c.diameter == 5.2 mm, "M5 Chicago screw pivot"
    assert b[0].pivot.c.center.x - b[0].body.bb.left == 20 mm, "pivot 20 from the end"
    for i in range(4) {
        assert b[i].label.bb.right <= b[i].number.bb.left - 3 mm, "name clear of the number"
        assert b[i].label.bb.left - b[i].pivot.bb.right >= 5 mm, "name clear of the screw"
    }
    assert cover.label.bb.right <= cover.number.bb.left - 3 mm, "cover title clear of the year"
}
