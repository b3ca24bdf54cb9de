# Kalimba (thumb piano) soundboard top, 4 mm plywood: 140 mm wide, straight sides
# 80 mm tall, and an arched top edge that rises to 110 mm in the middle (a circular
# arc through the tops of the sides). A 32 mm sound hole centred left-right, its centre
# 45 mm above the bottom edge, ringed by a rosette of 12 holes of 4 mm on a 24 mm radius
# around it (the first straight up). Two 3.5 mm screw holes for the tine bridge, 55 mm
# apart, centred, 85 mm above the bottom edge, countersunk 7 mm.
# "KALIMBA" engraved 6 mm tall, centred, baseline 8 mm above the bottom edge.

units mm
thickness 4 mm

param width = 140 mm, min = 100 mm, max = 180 mm
param side = 80 mm, min = 60 mm, max = 100 mm
param crown = 110 mm, min = 90 mm, max = 140 mm

# the arch: a circle through (+-width/2, side) and (0, crown)
sag = crown - side
R = ((width / 2) ** 2 + sag ** 2) / (2 * sag)

solid top {
    box = Rectangle(bottom_left=(-width / 2, 0), width=width, height=crown, construction=true)
    arch = Circle(center=(0, crown - R), radius=R, construction=true)
    board = Intersect(box, arch)

    hole sound {
        c = Circle(center=(0, 45), diameter=32)
    }
    hole rose {
        c = Circle(center=(0, 45 + 24), diameter=4)
    }
    rosette = CircularPattern(rose, 12, sound.c.center)
    VerticalDistance(sound.c.center, rose.c.center, 24)
    AlignCenterX(rose, sound)

    hole bridge {
        c = Circle(center=(-27.5, 85), diameter=3.5)
    }
    screws = LinearPattern(bridge, 2, (55, 0))
    Countersink(bridge, diameter=7)

    drawing label {
        t = Text("KALIMBA", (0, 8), size=6)
    }

    assert self.bb.width == 140 mm, "140 mm wide"
    assert self.bb.top - self.bb.bottom == 110 mm, "110 mm at the crown"
    assert sound.c.diameter == 32 mm and sound.c.center.y - self.bb.bottom == 45 mm, "sound hole 32, 45 up"
    assert abs(sound.c.center.x - self.bb.center_x) < 0.01 mm, "sound hole centred"
    assert len(rosette) == 12, "12 rosette holes"
    assert abs(distance(rosette[3].c.center, sound.c.center) - 24 mm) < 0.01 mm, "rosette on r 24"
    assert rosette[0].c.diameter == 4 mm, "4 mm rosette holes"
    assert screws[1].c.center.x - screws[0].c.center.x == 55 mm, "bridge screws 55 apart"
    assert screws[0].c.center.y - self.bb.bottom == 85 mm, "bridge screws 85 up"
    assert abs((screws[0].c.center.x + screws[1].c.center.x) / 2 - self.bb.center_x) < 0.01 mm, "bridge screws centred"
    assert label.t.size == 6 mm and label.t.position.y - self.bb.bottom == 8 mm, "label 6 mm, 8 up"
}
