# Request (music): a pan-pipe binding plate, 3 mm ply: a 180 x 34 mm strip with
# eight holes for copper tubes, diameters 16, 15, 14, 13, 12, 11, 10, 9 mm (+0.3 mm
# clearance), centres 20 mm apart, 14 mm up from the bottom edge, the first 20 mm from
# the left end; the note names C D E F G A B C engraved 4 mm tall under... above each hole;
# a 4 mm lanyard hole in the right end, 8 mm from the end; the top edge a gentle arc
# rising 6 mm in the middle (the strip 34 at the ends, 40 in the middle).
thickness 3 mm
kerf 0.15 mm

dias = [16, 15, 14, 13, 12, 11, 10, 9]
notes = ["C", "D", "E", "F", "G", "A", "B", "C"]

solid strip {
    base = Line((0, 0), (180, 0))
    r = Line((180, 0), (180, 34))
    top = Arc(start=(180, 34), through=(90, 40), end=(0, 34))
    l = Line((0, 34), (0, 0))
    for i in range(8) {
        hole tube { c = Circle(center=(20 + i * 20, 14), diameter=dias[i] + 0.3) }
        drawing note { t = Text(notes[i], position=(20 + i * 20, 26), size=4) }
    }
    hole lanyard { c = Circle(center=(172, 28), diameter=4) }
    assert len(tube) == 8, "eight tubes"
    assert tube[7].c.center.x - tube[0].c.center.x == 140 mm, "20 mm apart"
    assert tube[0].c.diameter == 16.3 mm, "16 mm + clearance"
}
