# Playing-card holder for small hands: a 100 mm disc (two are glued face to
# face in use; this is one layer) with a curved slit that grips the cards: an
# arc of radius 38 mm about the disc's center from 30 to 150 deg, cut as a
# single line (a kerf-wide slit); a 25 mm finger hole in the middle; "ACE" 
# engraved 7 mm high under the finger hole, centered 22 mm below the center.
thickness 3 mm

solid holder {
    disc = Circle(center=(0, 0), diameter=100)
    cut slit {
        a = Arc(center=(0, 0), radius=38, start_angle=30 deg, end_angle=150 deg)
    }
    hole finger {
        c = Circle(center=(0, 0), diameter=25)
    }
    drawing label {
        t = Text("ACE", position=(0, -22), size=7, valign="middle")
    }
}

assert holder.disc.diameter == 100 mm, "100 mm disc"
assert holder.slit.a.radius == 38 mm, "slit radius 38"
assert holder.finger.c.diameter == 25 mm, "25 mm finger hole"
assert holder.disc.center.y - holder.label.t.position.y == 22 mm, "label 22 mm below"
assert holder.label.t.bb.top < holder.finger.bb.bottom, "label under the finger hole"
