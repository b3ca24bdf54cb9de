# Push-along toy car, 6 mm plywood, parts to glue: three identical body layers (glued face to
# face: an 18 mm body) and four wheels.
# Body layer (car facing +x): a lower body 140 x 30 mm with 6 mm corner radii; on it a cabin, a
# trapezoid 80 mm wide at the bottom, 55 mm at the top, 24 mm tall, its centre 10 mm behind
# (toward -x) the lower body's centre. Two side windows cut through the cabin: 5 mm in from its
# top, its bottom and its sloped sides, split by a 4 mm pillar in the cabin's middle.
# Axle holes 6.5 mm (a 6 mm dowel turns in them) 28 mm from each end, 10 mm above the bottom.
# A 5 mm pull-string hole 8 mm from the front end, 15 mm above the bottom.
# Wheel: 36 mm disc, 6 mm bore (glued on the dowel), five 6 mm lightening holes on a 20 mm
# pitch circle, an engraved tyre line 30 mm across.
# Layout for cutting: layers 70 mm apart in y, wheels in a row below them, 45 mm apart.
units mm
thickness 6 mm

def body_layer(x0=0 mm, y0=0 mm) -> solid {
    lower = RoundedRectangle(bottom_left=(x0, y0), width=140, height=30, corner_radius=6)
    cabin = Trapezoid(center=(x0 + 60, y0 + 42), bottom_width=80, top_width=55, height=24)
    Above(cabin, lower)
    cabin.bb.center_x == lower.bb.center_x - 10 mm

    # sloped side: 12.5 mm in over 24 mm up; 5 mm square to it is 5.64 mm along x
    hole windows {
        rear = Polygon([(x0 + 20 + 12.5 * 5 / 24 + 5.64, y0 + 35), (x0 + 58, y0 + 35),
                        (x0 + 58, y0 + 49), (x0 + 20 + 12.5 * 19 / 24 + 5.64, y0 + 49)])
        front = Polygon([(x0 + 62, y0 + 35), (x0 + 100 - 12.5 * 5 / 24 - 5.64, y0 + 35),
                         (x0 + 100 - 12.5 * 19 / 24 - 5.64, y0 + 49), (x0 + 62, y0 + 49)])
    }
    hole axles {
        rear = Circle(center=(x0 + 28, y0 + 10), diameter=6.5)
        front = Circle(center=(x0 + 140 - 28, y0 + 10), diameter=6.5)
    }
    hole string {
        c = Circle(center=(x0 + 140 - 8, y0 + 15), diameter=5)
    }
}

def wheel(x0=0 mm, y0=0 mm) -> solid {
    disc = Circle(center=(x0, y0), diameter=36)
    hole bore {
        c = Circle(center=(x0, y0), diameter=6)
    }
    hole light {
        c = Circle(center=(x0, y0 + 10), diameter=6)
    }
    lights = CircularPattern(light, 5, (x0, y0))
    drawing tyre {
        ring = Circle(center=(x0, y0), diameter=30)
    }
}

assembly toy_car {
    for i in range(3) {
        layer = body_layer(x0=0 mm, y0=i * 70 mm)
    }
    for i in range(4) {
        w = wheel(x0=20 mm + i * 45 mm, y0=-30 mm)
    }

    # the request's numbers
    assert len(layer) == 3 and len(w) == 4, "three layers, four wheels"
    assert layer[0].lower.width == 140 mm and layer[0].lower.height == 30 mm, "lower body"
    assert layer[0].cabin.bottom_width == 80 mm and layer[0].cabin.top_width == 55 mm, "cabin"
    assert layer[0].cabin.height == 24 mm, "cabin height"
    assert layer[0].cabin.bb.bottom == layer[0].lower.bb.top, "cabin on the body"
    assert layer[0].lower.bb.center_x - layer[0].cabin.bb.center_x == 10 mm, "cabin 10 mm back"
    assert abs(layer[0].cabin.bb.top - layer[0].windows.bb.top - 5 mm) < 0.01 mm, "5 mm from the top"
    assert abs(layer[0].windows.bb.bottom - layer[0].cabin.bb.bottom - 5 mm) < 0.01 mm, "5 mm from the bottom"
    assert abs(layer[0].windows.front.bb.left - layer[0].windows.rear.bb.right - 4 mm) < 0.01 mm, "4 mm pillar"
    assert abs((layer[0].windows.front.bb.left + layer[0].windows.rear.bb.right) / 2 - layer[0].cabin.bb.center_x) < 0.01 mm, "pillar in the middle"
    assert layer[0].axles.rear.center.x - layer[0].lower.bb.left == 28 mm, "rear axle 28 mm in"
    assert layer[0].lower.bb.right - layer[0].axles.front.center.x == 28 mm, "front axle 28 mm in"
    assert layer[0].axles.rear.center.y - layer[0].lower.bb.bottom == 10 mm, "axles 10 mm up"
    assert layer[0].axles.rear.diameter == 6.5 mm, "axle holes 6.5 mm"
    assert layer[0].lower.bb.right - layer[0].string.c.center.x == 8 mm, "string hole 8 mm in"
    assert layer[0].string.c.center.y - layer[0].lower.bb.bottom == 15 mm, "string hole 15 mm up"
    assert w[0].disc.diameter == 36 mm and w[0].bore.c.diameter == 6 mm, "wheel and bore"
    assert len(w[0].lights) == 5 and w[0].light.c.diameter == 6 mm, "five 6 mm holes"
    assert w[0].light.c.center.y - w[0].disc.center.y == 20 mm / 2, "20 mm pitch circle"
    assert w[0].tyre.ring.diameter == 30 mm, "tyre line 30 mm"
    assert layer[1].lower.bb.bottom - layer[0].lower.bb.bottom == 70 mm, "layers 70 mm apart"
    assert w[1].disc.center.x - w[0].disc.center.x == 45 mm, "wheels 45 mm apart"
}
