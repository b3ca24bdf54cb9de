# Toys: a flat toy tractor, 6 mm plywood, three parts. Body: a side silhouette 150 mm long,
# 110 mm tall from the ground line (cab at the rear with a 40 x 30 mm window, hood in front,
# a 6 x 20 mm exhaust on the hood), two 6.2 mm axle holes. Rear wheel 70 mm, front wheel 40 mm,
# each with a 6.2 mm axle hole and five lightening holes (20 % of the wheel's diameter, at 30 %
# of it from the centre). Both wheels stand on one ground line, rear axle 40 mm and front axle
# 120 mm from the tractor's rear end. "FARM" in bold sans, 10 mm, engraved filled on the hood.

thickness 6 mm

def wheel(d=70 mm) -> solid {
    rim = Circle(center=(0, 0), diameter=d)
    hole axle { c = Circle(center=(0, 0), diameter=6.2) }
    Concentric(axle.c, rim)
    hole window { w = Circle(center=(0, 0.3 * d), diameter=0.2 * d) }
    At(window.w.center, rim.center, dy=0.3 * d)
    CircularPattern(window, 5, rim.center)
}

assembly tractor {
    solid body {
        shell = Polygon([(0, 12), (150, 12), (150, 60), (80, 65), (75, 110), (15, 110),
                         (10, 65), (0, 60)])
        solid exhaust { pipe = Rectangle(center=(130, 70), width=6, height=20) }
        # the pipe stands on the hood, its foot buried 4 mm into it
        exhaust.pipe.bottom.midpoint.y == 58
        hole cab_window { w = Rectangle(center=(45, 88), width=40, height=30) }
        hole rear_axle { c = Circle(center=(40, 35), diameter=6.2) }
        hole front_axle { c = Circle(center=(120, 20), diameter=6.2) }
        drawing label {
            word = Text("FARM", (115, 48), size=10, font="sans:Bold", fill=true, valign="middle")
        }
    }
    rear = wheel(d=70 mm)
    front = wheel(d=40 mm)
    Concentric(rear.rim, body.rear_axle.c)
    Concentric(front.rim, body.front_axle.c)
    AllowOverlap(rear, body)
    AllowOverlap(front, body)

    assert body.shell.bb.width == 150 mm, "body 150 long"
    assert body.shell.bb.top - rear.bb.bottom == 110 mm, "110 tall from the ground"
    assert rear.rim.diameter == 70 mm, "rear wheel 70"
    assert front.rim.diameter == 40 mm, "front wheel 40"
    assert abs(rear.bb.bottom - front.bb.bottom) < 0.01 mm, "both wheels on the ground line"
    assert rear.rim.center.x - body.shell.bb.left == 40 mm, "rear axle 40 from the rear"
    assert front.rim.center.x - body.shell.bb.left == 120 mm, "front axle 120 from the rear"
    assert body.cab_window.w.width == 40 mm and body.cab_window.w.height == 30 mm, "window 40 x 30"
}
