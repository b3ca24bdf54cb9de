# Request (sport): a floor stand for my recurve bow at the club, 9 mm birch ply, two plates
# cross-halved into an X. The upright is 350 mm tall, tapering from 220 mm wide at the floor
# to 70 mm at the top, where a cradle 45 mm wide and 40 mm deep (round-bottomed, to be lined
# with felt) holds the riser; its horns' outer corners rounded 5 mm. The cross foot is
# 300 mm tall, 220 mm at the floor and 90 mm at the top (corners rounded 10 mm). Both stand on
# two feet, an arch 120 mm wide and 40 mm high between them. The halving slots are 9.2 mm
# wide: the upright's from the floor up 150 mm, the foot's from its top down 150 mm. "ROBIN"
# engraved filled, 12 mm bold letters, on the foot's left wing 80 mm up, centred 50 mm left
# of the middle.

import "std/joints.aidl"

units mm
thickness 9 mm

t = 9 mm
cross = 150 mm        # the height where the two slots meet

solid_w = 220 mm

def upright() -> solid {
    body = Trapezoid(center=(0, 175), bottom_width=solid_w, top_width=70, height=350)
    hole cradle {
        s = Slot(center=(0, 350), length=80, width=45, rotation=90)
    }
    hole arch {
        e = Ellipse(center=(0, 0), rx=60, ry=40)
    }
    halving = cross_halving(depth=cross, thickness=t, clearance=0.2 mm, rotation=180 deg,
                            cx=0, cy=0)
    Fillet(body.top_left, 5)
    Fillet(body.top_right, 5)
}

def foot() -> solid {
    body = Trapezoid(center=(0, 150), bottom_width=solid_w, top_width=90, height=300)
    hole arch {
        e = Ellipse(center=(0, 0), rx=60, ry=40)
    }
    halving = cross_halving(depth=300 mm - cross, thickness=t, clearance=0.2 mm, cx=0, cy=300)
    drawing name {
        n = Text("ROBIN", (-50, 80), size=12, font="sans:Bold", fill=true)
    }
    Fillet(body.top_left, 10)
    Fillet(body.top_right, 10)
}

assembly bow_stand {
    a = upright()
    b = foot()

    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    # in 3D: the upright across x, the foot across y, both standing on z = 0
    Place(a, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(b, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))

    assert a.body.bb.height == 350 mm and b.body.bb.height == 300 mm, "350 and 300 tall"
    assert a.cradle.s.width == 45 mm, "cradle 45 wide"
    assert a.body.bb.top - a.cradle.s.bb.bottom == 40 mm, "cradle 40 deep"
    assert a.halving.depth + b.halving.depth == b.body.bb.height, "the slots meet"
    assert a.halving.depth == 150 mm, "upright's slot 150 up"
    assert a.arch.e.bb.width == 120 mm and a.arch.e.bb.top - a.body.bb.bottom == 40 mm, "arch 120 x 40"
}
