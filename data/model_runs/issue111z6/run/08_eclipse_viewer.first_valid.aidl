# Science: a hand-held solar-eclipse viewer from 3 mm plywood, two parts that sandwich a
# sheet of solar filter film with two M3 screws.
# Viewer card 160 x 70 mm, corners R12; a 60 x 20 mm window (R2 corners) for the film,
# centred left-right, its middle 10 mm above the card's centre; a 3.2 mm screw hole
# 38 mm each side of the window's middle; a nose notch in the bottom edge, half an
# ellipse 32 mm wide and 20 mm deep, centred; "ECLIPSE 2027" in bold sans 7 mm high,
# filled engraving, centred 27.5 mm above the card's centre; "ONLY LOOK THROUGH THE
# FILTER" engraved 3 mm high, centred 8 mm below the card's centre.
# Filter frame 88 x 32 mm, corners R3, with the same window and the same two holes,
# centred.

thickness 3 mm

param win_w = 60 mm, min = 40 mm, max = 80 mm
param win_h = 20 mm, min = 12 mm, max = 30 mm

def filter_cut(w=60 mm, h=20 mm) -> hole {
    window = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=2)
    left = Circle(center=(-38, 0), diameter=3.2)
    right = Circle(center=(38, 0), diameter=3.2)
}

assembly viewer_kit {
    solid viewer {
        card = RoundedRectangle(center=(0, 0), width=160, height=70, corner_radius=12)
        Fixed(card)
        win = filter_cut(w=win_w, h=win_h)
        AlignCenterX(win, card)
        win.window.center.y == card.center.y + 10 mm
        hole nose {
            e = Ellipse(center=(0, -35), rx=16, ry=20)
        }
        drawing title {
            t = Text("ECLIPSE 2027", position=(0, 27.5), size=7, font="sans:Bold",
                     valign="middle", fill=true)
        }
        drawing warning {
            t = Text("ONLY LOOK THROUGH THE FILTER", position=(0, -8), size=3, valign="middle")
        }
    }

    solid frame {
        body = RoundedRectangle(center=(0, -80), width=88, height=32, corner_radius=3)
        Fixed(body)
        win = filter_cut(w=win_w, h=win_h)
        CenterInside(win, body)
    }

    assert viewer.card.width == 160 mm and viewer.card.height == 70 mm, "card 160 x 70"
    assert viewer.win.window.width == 60 mm and viewer.win.window.height == 20 mm, "window 60 x 20"
    assert viewer.win.window.center.y - viewer.card.center.y == 10 mm, "window 10 mm above the centre"
    assert viewer.win.right.center.x - viewer.win.window.center.x == 38 mm, "screws 38 mm each side"
    assert viewer.nose.e.rx * 2 == 32 mm and viewer.nose.e.center.y + viewer.nose.e.ry - viewer.card.bb.bottom == 20 mm, "nose 32 wide, 20 deep"
    assert frame.body.width == 88 mm and frame.body.height == 32 mm, "frame 88 x 32"
    assert frame.win.window.center.x == frame.body.center.x and frame.win.window.center.y == frame.body.center.y, "frame window centred"
}
