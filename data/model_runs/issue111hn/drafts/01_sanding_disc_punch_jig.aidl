# Request (workshop): a punching jig for 125 mm hook-and-loop sanding discs, so I can
# punch the dust holes my sander needs into cheap unholed discs. My sander's pattern: 8
# holes of 10 mm on a 90 mm circle, the first at 12 o'clock, plus a 10 mm centre hole.
# Three 6 mm MDF layers, each 170 x 170 with 8 mm rounded corners:
# - a backer with 12 mm relief holes under every punch hole (the hollow punch goes through);
# - a locating frame with a 126 mm round pocket the disc drops into;
# - a lid with 10.2 mm guide holes for the 10 mm hollow punch, the disc's 125 mm outline
#   engraved, and "125 mm HOOK & LOOP - 8 HOLE" engraved along the inside of that outline
#   at the bottom.
# Four 6 mm dowel holes 15 mm in from each corner, through all three layers, line them up;
# an 8 mm hanging hole at the top centre of each layer, 11 mm down from the top edge.

units mm
thickness 6 mm

param plate = 170 mm, min = 150 mm, max = 220 mm
disc_d = 125 mm
pocket_d = 126 mm
pcd = 90 mm
guide_d = 10.2 mm
relief_d = 12 mm
dowel_d = 6 mm
dowel_in = 15 mm
hang_d = 8 mm
hang_down = 11 mm

def dowel() -> hole {
    c = Circle(center=(0, 0), diameter=dowel_d)
}

def hanger() -> hole {
    c = Circle(center=(0, plate / 2 - hang_down), diameter=hang_d)
}

assembly jig {
    solid backer {
        body = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=8)
        hole relief { c = Circle(center=(0, pcd / 2), diameter=relief_d) }
        reliefs = CircularPattern(relief, 8, (0, 0))
        hole centre { c = Circle(center=(0, 0), diameter=relief_d) }
        d = dowel()
        dowels = CornerPattern(d, body, inset=dowel_in)
        hang = hanger()
    }

    solid frame {
        body = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=8)
        hole pocket { c = Circle(center=(0, 0), diameter=pocket_d) }
        d = dowel()
        dowels = CornerPattern(d, body, inset=dowel_in)
        hang = hanger()
    }

    solid lid {
        body = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=8)
        hole guide { c = Circle(center=(0, pcd / 2), diameter=guide_d) }
        guides = CircularPattern(guide, 8, (0, 0))
        hole centre { c = Circle(center=(0, 0), diameter=guide_d) }
        d = dowel()
        dowels = CornerPattern(d, body, inset=dowel_in)
        hang = hanger()
        drawing marks {
            outline = Circle(center=(0, 0), diameter=disc_d)
            ring = Circle(center=(0, 0), radius=58, construction=true)
            label = Text("125 mm HOOK & LOOP - 8 HOLE", along=ring, flip=true, size=4)
        }
    }

    RightOf(frame, backer, gap=10)
    AlignTop(frame, backer)
    RightOf(lid, frame, gap=10)
    AlignTop(lid, frame)

    # stacked for the assembled view: backer, frame, lid
    Place(backer, position=(0, 0, 0))
    Place(frame, position=(0, 0, 6))
    Place(lid, position=(0, 0, 12))

    assert len(backer.reliefs) == 8, "8 dust holes"
    assert len(lid.guides) == 8, "8 guide holes"
    assert distance(lid.guide.c.center, lid.body.center) == 45 mm, "holes on a 90 mm circle"
    assert lid.guide.c.center.y - lid.body.center.y == 45 mm, "first hole at 12 o'clock"
    assert frame.pocket.c.diameter - disc_d == 1 mm, "the disc drops into the pocket"
    assert backer.body.bb.width == 170 mm and lid.body.bb.height == 170 mm, "170 x 170 layers"
    assert lid.body.bb.top - lid.hang.c.center.y == 11 mm, "hanging hole 11 mm down"
    assert frame.dowels[2].c.center.x - frame.body.center.x == 70 mm, "dowels 15 mm in"
    assert distance(frame.hang.c, frame.pocket.c) >= 3 mm, "wall between hanging hole and pocket"
}
