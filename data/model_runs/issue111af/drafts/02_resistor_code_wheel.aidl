# Request (electronics): a resistor colour-code wheel for the bench, 3 mm plywood, four parts
# riveted on one M3 screw (3.2 mm hole in every part):
# - base dial, 150 mm across: multiplier ring (x1 ... x1G) with the 10 colour names, and the
#   title "RESISTOR COLOUR CODE" engraved round its bottom edge;
# - middle dial, 100 mm across: the 10 colours with digits 0-9 (2nd band);
# - top dial, 70 mm across: the 10 colours with digits 0-9 (1st band);
# - a pointer arm 26 mm wide from 20 mm behind the centre to 75 mm out, with three 20 mm wide
#   windows, one over each dial's visible ring, so the three readings line up.
# Colours in order black, brown, red, orange, yellow, green, blue, violet, grey, white, 36 deg
# apart, clockwise from the top.

units mm
thickness 3 mm

pin_d = 3.2 mm
colours = ["BLACK", "BROWN", "RED", "ORANGE", "YELLOW", "GREEN", "BLUE", "VIOLET", "GREY", "WHITE"]
digits = ["0", "1", "2", "3", "4", "5", "6", "7", "8", "9"]
mults = ["x1", "x10", "x100", "x1k", "x10k", "x100k", "x1M", "x10M", "x100M", "x1G"]

def dial(r=35 mm, marks=digits, rd=23 mm, sd=5 mm, rn=29.5 mm, sn=2.5 mm) -> solid {
    body = Circle(center=(0, 0), radius=r)
    hole pin { c = Circle(center=(0, 0), diameter=pin_d) }
    drawing labels {
        ring_d = Circle(center=(0, 0), radius=rd, construction=true)
        ring_n = Circle(center=(0, 0), radius=rn, construction=true)
        for i in range(10) {
            d = Text(marks[i], along=ring_d, angle=90 deg - i * 36 deg, size=sd)
            n = Text(colours[i], along=ring_n, angle=90 deg - i * 36 deg, size=sn)
        }
    }
    # FIX after the first valid program: 20 W0513 "text ... is drawn over text" on this dial's
    # labels were false alarms (boxes of letters turned round the circle overlap, the letters do
    # not: checked on a 3000 px render); accepted as the prompt says.
    AllowOverlap(labels)
    Fixed(body)
    Concentric(pin.c, body)
    Concentric(labels.ring_d, body)
    Concentric(labels.ring_n, body)
}

assembly resistor_wheel {
    base = dial(r=75 mm, marks=mults, rd=53 mm, sd=4 mm, rn=59 mm, sn=3 mm)
    drawing title {
        ring = Circle(center=(0, 0), radius=72, construction=true)
        t = Text("RESISTOR COLOUR CODE", along=ring, flip=true, size=4)
    }
    CutInto(title, base)
    AllowOverlap(title, base.labels)
    Concentric(title.ring, base.body)

    middle = dial(r=50 mm, marks=digits, rd=38 mm, sd=5 mm, rn=44.5 mm, sn=3 mm)
    top = dial(r=35 mm, marks=digits, rd=23 mm, sd=5 mm, rn=29.5 mm, sn=2.5 mm)

    solid pointer {
        arm = Slot(start=(0, -20 + 13), end=(0, 75 - 13), width=26)
        hole pin { c = Circle(center=(0, 0), diameter=pin_d) }
        hole windows {
            w1 = Rectangle(center=(0, 27.75), width=20, height=10.5)
            w2 = Rectangle(center=(0, 42.75), width=20, height=10.5)
            w3 = Rectangle(center=(0, 57.75), width=20, height=10.5)
        }
        Fixed(arm)
    }

    # laid side by side for cutting
    RightOf(middle, base, gap=10)
    RightOf(top, middle, gap=10)
    RightOf(pointer, top, gap=10)
    AlignCenterY(middle, base)
    AlignCenterY(top, base)
    AlignCenterY(pointer, base)

    assert len(colours) == 10, "10 colours"
    assert base.body.diameter == 150 mm, "base 150 across"
    assert middle.body.diameter == 100 mm, "middle 100 across"
    assert top.body.diameter == 70 mm, "top 70 across"
    assert pointer.arm.width == 26 mm, "pointer 26 wide"
    assert pointer.arm.bb.height == 95 mm, "pointer from -20 to 75"
    assert pointer.windows.w1.width == 20 mm, "windows 20 wide"
    assert base.pin.c.diameter == 3.2 mm and pointer.pin.c.diameter == 3.2 mm, "M3 rivet"
}
