# Holidays: Christmas gingerbread-house front (a tea-light house), 3 mm MDF. A house outline
# 160 mm wide, walls 100 mm tall, the roof rising to a peak 160 mm above the bottom. Door 36 mm
# wide, 60 mm tall overall with a round top (R18), centred, open at the bottom edge. Two
# windows centred 45 mm either side of the centre line at 65 mm up, each four 13 x 13 mm panes
# with 4 mm bars between them. A heart about 22 mm wide cut out in the gable, centred 115 mm
# up. Both 100 mm wall edges cut into finger joints (3 mm material, 10 mm fingers, starting
# with a tab) for the side walls.
import "std/joints.aidl"

thickness 3 mm

def window_panes() -> hole {
    for i in range(2) {
        for j in range(2) {
            p = Rectangle(center=((i - 0.5) * 17 mm, (j - 0.5) * 17 mm), width=13, height=13)
        }
    }
}

solid front {
    body = Polygon([(-80, 0), (80, 0), (80, 100), (0, 160), (-80, 100)])

    hole door {
        lower = Rectangle(bottom_left=(-18, 0), width=36, height=42)
        arch = Circle(center=(0, 42), radius=18)
    }

    wl = window_panes()
    wr = window_panes()
    wl.bb.center == (-45, 65)
    wr.bb.center == (45, 65)

    hole heart {
        a = Circle(center=(-5, 121), radius=6)
        b = Circle(center=(5, 121), radius=6)
        v = Triangle(center=(0, 112), base=22, height=14, rotation=180 deg)
    }

    left_joint = finger_edge(length=100 mm, thickness=3 mm, finger=10 mm, start="tab", rotation=90 deg, cx=-80 mm, cy=50 mm)
    right_joint = finger_edge(length=100 mm, thickness=3 mm, finger=10 mm, start="tab", rotation=-90 deg, cx=80 mm, cy=50 mm)

    assert body.bb.width == 160 mm, "160 wide"
    assert body.bb.height == 160 mm, "peak 160 up"
    assert door.bb.width == 36 mm and door.bb.height == 60 mm, "door 36 x 60"
    assert len(wl.p) == 2 and len(wl.p[0]) == 2, "four panes"
    assert wl.bb.width == 13 mm * 2 + 4 mm, "two panes and a 4 mm bar"
    assert wr.bb.center_x - wl.bb.center_x == 90 mm, "windows 45 either side"
}
