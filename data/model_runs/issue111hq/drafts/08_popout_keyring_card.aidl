# Request (gifts): a new-home card for Ben and Sam, 3 mm birch ply, A6 (148 x 105 mm, 5 mm
# corners), with a house-shaped keyring that presses out of it. The keyring: a house 40 mm
# wide, walls 35 mm tall and a roof peak 50 mm above its floor, centred 42 mm right of the
# card's centre and 5 mm below it; its outline is cut through except for three 1.2 mm
# bridges (middle of the floor, middle of each wall) that hold it until pressed out. In it a
# 4 mm key-ring hole 10 mm below the peak, "14" engraved filled in bold 7 mm tall, and a
# heart window 14 mm wide. On the card, left of the house: "HOME / SWEET / HOME" engraved
# filled in bold serif 10 mm tall, centred on x = -26 mm, and "Ben & Sam · 14 Elm Road"
# engraved filled in italic serif 4.5 mm tall under them; "PRESS OUT" 3 mm under the house.

thickness 3 mm

hx = 42 mm
hy = -5 mm
half = 20 mm
floor_y = hy - 25 mm
eave_y = floor_y + 35 mm
peak_y = floor_y + 50 mm
wall_mid = floor_y + 17.5 mm
gap = 1.2 mm

solid card {
    body = RoundedRectangle(center=(0, 0), width=148, height=105, corner_radius=5)
    Fixed(body)

    cut keyring_outline {
        a = Polyline([(hx + gap / 2, floor_y), (hx + half, floor_y), (hx + half, wall_mid - gap / 2)])
        b = Polyline([(hx + half, wall_mid + gap / 2), (hx + half, eave_y), (hx, peak_y),
                      (hx - half, eave_y), (hx - half, wall_mid + gap / 2)])
        c = Polyline([(hx - half, wall_mid - gap / 2), (hx - half, floor_y), (hx - gap / 2, floor_y)])
    }
    hole ring {
        c = Circle(center=(hx, peak_y - 10), diameter=4)
    }
    hole heart {
        l = Hull(Circle(center=(hx - 3.1, floor_y + 10.5), radius=3.9), Point(hx, floor_y + 3))
        r = Hull(Circle(center=(hx + 3.1, floor_y + 10.5), radius=3.9), Point(hx, floor_y + 3))
    }
    drawing number {
        t = Text("14", (hx, floor_y + 22), size=7, font="sans:Bold", valign="middle", fill=true)
    }
    drawing greeting {
        l1 = Text("HOME", (-26, 26), size=10, font="serif:Bold", valign="middle", fill=true)
        l2 = Text("SWEET", (-26, 9), size=10, font="serif:Bold", valign="middle", fill=true)
        l3 = Text("HOME", (-26, -8), size=10, font="serif:Bold", valign="middle", fill=true)
        who = Text("Ben & Sam · 14 Elm Road", (-26, -30), size=4.5, font="serif:Italic",
                   valign="middle", fill=true)
    }
    drawing press {
        t = Text("PRESS OUT", (hx, floor_y - 5), size=3, valign="top")
    }

    assert keyring_outline.bb.width == 40 mm, "house 40 mm wide"
    assert keyring_outline.bb.height == 50 mm, "peak 50 mm above the floor"
    assert eave_y - floor_y == 35 mm, "walls 35 mm"
    assert abs(keyring_outline.bb.center_x - body.bb.center_x - 42 mm) < 0.01 mm, "42 mm right"
    assert abs(keyring_outline.bb.bottom + 25 mm - (body.bb.center_y - 5 mm)) < 0.01 mm,
        "centred 5 mm below the card's centre"
    assert distance(keyring_outline.b.start, keyring_outline.a.end) == 1.2 mm, "1.2 mm bridge"
    assert distance(keyring_outline.a.start, keyring_outline.c.end) == 1.2 mm, "1.2 mm bridge"
    assert distance(keyring_outline.c.start, keyring_outline.b.end) == 1.2 mm, "1.2 mm bridge"
    assert peak_y - ring.c.center.y == 10 mm, "ring hole 10 mm below the peak"
    assert abs(heart.bb.width - 14 mm) < 0.1 mm, "heart 14 mm wide"
    assert distance(ring, keyring_outline) >= 3 mm, "ply round the ring hole"
    assert distance(heart, keyring_outline) >= 2.5 mm, "ply round the heart"
    assert distance(number, heart) >= 1.5 mm and distance(number, ring) >= 1.5 mm,
        "14 clears the heart and the ring hole"
    assert distance(greeting, keyring_outline) >= 5 mm, "the greeting stays off the keyring"
    assert greeting.bb.left >= body.bb.left + 6 mm, "the greeting stays on the card"
    assert distance(press, keyring_outline) >= 1.5 mm, "PRESS OUT under the house"
}
