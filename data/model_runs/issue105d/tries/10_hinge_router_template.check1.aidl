# Router template for a 35 mm hinge cup, cut with a 30 mm guide bushing and a 12 mm bit:
# a 120 x 100 mm plate (4 mm rounded corners) with a round opening of 35 + 30 - 12 = 53 mm
# diameter, centred left-right; an engraved line 30 mm above the bottom edge marks the
# door edge; the opening's centre is 22.5 mm above that line (the cup's centre);
# engraved centre marks (two 10 mm ticks on each axis outside the opening) and the text
# "35 CUP / 30 BUSH / 12 BIT" 4 mm tall near the top; two 5 mm clamp-screw holes 12 mm
# from the left and right edges on the cup's centre line.
param cup = 35 mm, min = 26 mm, max = 40 mm
param bushing = 30 mm, min = 16 mm, max = 40 mm
param bit = 12 mm, min = 6 mm, max = 16 mm
param edge_to_center = 22.5 mm, min = 20 mm, max = 25 mm
thickness 6 mm

solid template {
    plate = RoundedRectangle(center=(0, 0), width=120, height=100, corner_radius=4)
    hole opening { c = Circle(center=(0, 2.5), diameter=cup + bushing - bit) }
    drawing door_edge { l = Line((-60, -20), (60, -20)) }
    Horizontal(door_edge.l)
    Coincident(door_edge.l.start, plate.left)
    Coincident(door_edge.l.end, plate.right)
    door_edge.l.start.y == plate.bb.bottom + 30
    At(opening.c.center, door_edge.l.midpoint, dy=edge_to_center)
    drawing marks {
        top = Line((0, 30), (0, 40))
        bottom = Line((0, -35), (0, -25))
        left = Line((-40, 2.5), (-30, 2.5))
        right = Line((30, 2.5), (40, 2.5))
    }
    Rigid(marks)
    At(marks.top.start, opening.c.top, dy=2)
    hole clamp_l { c = Circle(center=(-48, 2.5), diameter=5) }
    hole clamp_r { c = Circle(center=(48, 2.5), diameter=5) }
    At(clamp_l.c.center, (plate.bb.left + 12, opening.c.center.y))
    At(clamp_r.c.center, (plate.bb.right - 12, opening.c.center.y))
    drawing note { t = Text("35 CUP / 30 BUSH / 12 BIT", (0, 42), size=4, valign="middle") }
    At(note.t.position, plate.bb.top_left, dx=60, dy=-8)
    assert opening.c.diameter == 53 mm, "53 mm opening"
    assert opening.c.center.y - door_edge.l.start.y == 22.5 mm, "cup centre 22.5 mm from the door edge"
    assert marks.bb.right < clamp_r.bb.left, "ticks clear of the clamp holes"
    assert note.bb.bottom > marks.top.end.y, "note above the top tick"
}
