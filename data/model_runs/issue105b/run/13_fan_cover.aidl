# Cover (finger guard) for a 120 mm PC fan, 3 mm acrylic: a 120 x 120 mm plate
# with 6 mm rounded corners; four 4.3 mm screw holes on the fan's 105 mm square
# pattern; the grill is 5 concentric rings of arc slots 6 mm wide on center-line
# radii 15, 25, 35, 45 and 53 mm, each ring broken into 4 arcs by 6 mm bridges on
# the diagonals, all centered on the plate; the 12 mm center stays solid.

units mm
thickness 3 mm

param bridge = 6 mm, min = 3 mm, max = 10 mm

radii = [15 mm, 25 mm, 35 mm, 45 mm, 53 mm]

solid cover {
    plate = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=6)
    pattern = Rectangle(center=(0, 0), width=105, height=105, construction=true)
    Concentric(pattern, plate)

    hole screw {
        c = Circle(center=(0, 0), diameter=4.3)
    }
    screws = CornerPattern(screw, pattern)

    hole grill {
        for r in radii {
            for q in range(4) {
                a = ArcSlot(center=(0, 0), radius=r,
                            start_angle=45 deg + q * 90 deg + (bridge + 6) / 2 / r * 1 rad,
                            end_angle=135 deg + q * 90 deg - (bridge + 6) / 2 / r * 1 rad,
                            width=6)
            }
        }
    }
    Rigid(grill)
    CenterInside(grill, plate)
}
