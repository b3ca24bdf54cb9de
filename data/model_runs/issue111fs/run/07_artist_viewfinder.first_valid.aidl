# Request (crafts): "A pocket viewfinder for sketching outdoors, from 3 mm black acrylic (engraving
# shows white): a card 150 x 100 mm with R5 corners. Two windows: a 4:3 window 64 x 48 mm centred
# at (-30, 10) from the card's centre and a square window 36 x 36 centred at (42, 16). Around each
# window, rule-of-thirds ticks engraved outside its edges: at a third and two thirds along every
# edge, 4 mm long, starting 2 mm from the edge. The ratio engraved under each window ("4:3",
# "1:1"). Along the bottom edge, a 120 mm ruler: a tick every mm (3 mm long, 5 mm at every 5,
# 7 mm at every 10), starting 2 mm in from the card's bottom edge, numbered every 10 mm. An 8 mm
# colour-isolation peephole in the top right corner area and a 5 mm lanyard hole top left, each
# at least 3 mm from every other feature and the edge."

W = 150 mm
H = 100 mm
ruler = 120 mm

def thirds(w=60 mm, h=40 mm) -> drawing {
    # ticks around a w x h window centred at (0, 0), 2 mm off its edges, 4 mm long
    for k in range(1, 3) {
        top = Line((-w / 2 + k * w / 3, h / 2 + 2), (-w / 2 + k * w / 3, h / 2 + 6))
        bottom = Line((-w / 2 + k * w / 3, -h / 2 - 2), (-w / 2 + k * w / 3, -h / 2 - 6))
        left = Line((-w / 2 - 2, -h / 2 + k * h / 3), (-w / 2 - 6, -h / 2 + k * h / 3))
        right = Line((w / 2 + 2, -h / 2 + k * h / 3), (w / 2 + 6, -h / 2 + k * h / 3))
    }
}

def tick(i) = 7 mm if i % 10 == 0 else (5 mm if i % 5 == 0 else 3 mm)

solid card {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=5)
    hole windows {
        a = Rectangle(center=(-30, 10), width=64, height=48)
        b = Rectangle(center=(42, 16), width=36, height=36)
    }
    hole peep {
        c = Circle(center=(66, 41), diameter=8)
    }
    hole lanyard {
        c = Circle(center=(-68, 43), diameter=5)
    }

    ta = thirds(w=64 mm, h=48 mm)
    ta.bb.center == (-30, 10)
    tb = thirds(w=36 mm, h=36 mm)
    tb.bb.center == (42, 16)

    drawing ratios {
        a = Text("4:3", position=(-30, -27), size=4, valign="middle")
        b = Text("1:1", position=(42, -27), size=4, valign="middle")
    }

    drawing scale {
        for i in range(121) {
            t = Line((-ruler / 2 + i * 1 mm, -H / 2 + 2), (-ruler / 2 + i * 1 mm, -H / 2 + 2 + tick(i)))
        }
        for k in range(13) {
            n = Text(str(10 * k), position=(-ruler / 2 + k * 10 mm, -H / 2 + 12), size=3, valign="middle")
        }
    }

    # the request's numbers
    assert body.width == 150 mm and body.height == 100 mm, "card 150 x 100"
    assert windows.a.width == 64 mm and windows.a.height == 48 mm, "4:3 window 64 x 48"
    assert windows.a.width / windows.a.height == 4 / 3, "4:3"
    assert windows.b.width == 36 mm and windows.b.height == 36 mm, "square window 36"
    assert windows.a.center.x - body.center.x == -30 mm and windows.a.center.y - body.center.y == 10 mm, "4:3 window at (-30, 10)"
    assert windows.b.center.x - body.center.x == 42 mm and windows.b.center.y - body.center.y == 16 mm, "square at (42, 16)"
    assert ta.top[0].start.x - windows.a.bb.left == 64 mm / 3, "a third along"
    assert ta.top[0].start.y - windows.a.bb.top == 2 mm, "ticks start 2 mm off the edge"
    assert ta.top[0].length == 4 mm and tb.right[1].length == 4 mm, "ticks 4 mm"
    assert tb.left[1].start.y - windows.b.bb.bottom == 2 * 36 mm / 3, "two thirds up the square"
    assert len(scale.t) == 121, "a tick every mm over 120 mm"
    assert scale.t[120].start.x - scale.t[0].start.x == 120 mm, "120 mm ruler"
    assert scale.t[0].start.y - body.bb.bottom == 2 mm, "ruler 2 mm in from the bottom edge"
    assert scale.t[10].length == 7 mm and scale.t[5].length == 5 mm and scale.t[3].length == 3 mm, "tick lengths"
    assert len(scale.n) == 13, "numbered every 10 mm"
    assert peep.c.diameter == 8 mm and lanyard.c.diameter == 5 mm, "8 mm peephole, 5 mm lanyard hole"
    # clearances
    assert distance(peep, windows) >= 3 mm and distance(peep, tb) >= 3 mm, "peephole clear"
    assert body.bb.right - peep.bb.right >= 3 mm and body.bb.top - peep.bb.top >= 3 mm, "peephole off the edge"
    assert distance(lanyard, windows) >= 3 mm and distance(lanyard, ta) >= 3 mm, "lanyard hole clear"
    assert lanyard.bb.left - body.bb.left >= 3 mm and body.bb.top - lanyard.bb.top >= 3 mm, "lanyard hole off the edge"
    assert distance(ratios, ta) >= 2 mm and distance(ratios, tb) >= 2 mm, "ratios clear of the ticks"
    assert distance(ratios, scale) >= 2 mm, "ratios clear of the ruler"
    assert distance(ta, tb) >= 2 mm, "the two windows' ticks apart"
}
