# Guest Wi-Fi sign: 150 x 100 mm plate, 10 mm rounded corners, standing in a slotted base
# (not part of this file); engraved: "WiFi" in filled sans Bold letters 16 mm tall near the
# top, centered; under it a Wi-Fi icon: a 6 mm dot and three concentric 90-degree arcs
# (radii 10, 17, 24 mm, 3 mm wide bands as ArcSlots) opening upward, centered; then
# "NETWORK:" and "PASSWORD:" labels in 5 mm single-stroke text at the left with 60 mm
# write-on lines after them; a 4 mm hanging hole 6 mm below the top in both top corners.

solid sign {
    body = RoundedRectangle(center=(0, 0), width=150, height=100, corner_radius=10)
    drawing title {
        t = Text("WiFi", position=(0, 30), size=16, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(title, body)
    title.bb.top == body.bb.top - 8 mm
    hole icon_dot {
        d = Circle(center=(0, -2), diameter=6)
    }
    drawing icon {
        dot = Circle(center=(0, -2), diameter=6)
        a1 = ArcSlot(center=(0, -2), radius=10, start_angle=45, end_angle=135, width=3)
        a2 = ArcSlot(center=(0, -2), radius=17, start_angle=45, end_angle=135, width=3)
        a3 = ArcSlot(center=(0, -2), radius=24, start_angle=45, end_angle=135, width=3)
    }
    drawing fields {
        net = Text("NETWORK:", position=(-65, -25), size=5, anchor="start")
        net_line = Line((-2, -25), (58, -25))
        pw = Text("PASSWORD:", position=(-65, -40), size=5, anchor="start")
        pw_line = Line((-2, -40), (58, -40))
    }
    hole hang {
        c = Circle(center=(-65, 44), diameter=4)
    }
    other = Mirrored(hang, Line((0, -50), (0, 50), construction=true))
    assert body.bb.width == 150 mm and body.bb.height == 100 mm, "150 x 100"
    assert fields.net_line.length == 60 mm and fields.pw_line.length == 60 mm, "60 mm lines"
    assert icon.a3.radius == 24 mm, "outer arc 24 mm"
    assert icon.bb.top < title.bb.bottom - 3 mm, "icon clear of the title"
    assert fields.bb.top < icon.bb.bottom - 3 mm, "fields clear of the icon"
}
