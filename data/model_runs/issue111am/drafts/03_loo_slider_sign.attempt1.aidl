# Request (bathroom): a "FREE / BUSY" slider sign for a bathroom door, 3 mm acrylic, three
# layers screwed to the door by four countersunk M4 screws (at x = +-70, y = +-18 from the
# centre). Front plate 160 x 50 R5 with a 36 x 14 window centred 20 mm right of the middle
# and "BATHROOM" cut through as a stencil (bold 8 mm) left of the window. Spacer plate 160 x 50
# with a 23 mm high channel from 60 mm left of the middle out through the right edge. Slider
# 150 x 22: "BUSY" engraved bold 6 mm 5 mm right of its middle and "FREE" 35 mm left of its
# middle (40 mm of travel), a 12 mm finger hole 65 mm right of its middle.
units mm
thickness 3 mm
import "std/fasteners.aidl"

def screws() -> hole {
    for i in range(4) {
        s = clearance_hole(size=4, cx=(-70 if i % 2 == 0 else 70), cy=(-18 if i < 2 else 18))
    }
}

assembly loo_sign {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=160, height=50, corner_radius=5)
        hole window {
            w = Rectangle(center=(20, 0), width=36, height=14)
        }
        hole word {
            t = Text("BATHROOM", (-30, 0), size=8, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        sc = screws()
        Countersink(sc, diameter=9 mm)
        assert window.w.center.x - body.center.x == 20 mm, "window 20 right of middle"
        assert word.bb.right < window.bb.left - 3, "word clear of the window"
    }
    solid spacer {
        body = RoundedRectangle(center=(0, -70), width=160, height=50, corner_radius=5)
        hole channel {
            c = Rectangle(corner=(-60, -81.5), opposite=(82, -58.5))
        }
        sc2 = screws()
        Translate(sc2, (0, -70))
        assert channel.c.height == 23 mm, "channel 23 high"
        assert channel.c.bb.left - body.center.x == -60 mm, "channel from 60 left of middle"
    }
    solid slider {
        strip = Rectangle(center=(0, -130), width=150, height=22)
        hole pull {
            f = Circle(center=(65, -130), diameter=12)
        }
        drawing words {
            busy = Text("BUSY", (5, -130), size=6, font="sans:Bold", valign="middle")
            free = Text("FREE", (-35, -130), size=6, font="sans:Bold", valign="middle")
        }
        assert words.busy.position.x - words.free.position.x == 40 mm, "40 mm of travel"
        assert pull.f.center.x - strip.center.x == 65 mm, "finger hole"
    }
    assert slider.strip.height < spacer.channel.c.height, "slider fits the channel"
}
