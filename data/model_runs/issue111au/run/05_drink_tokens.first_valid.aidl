# Request: drink tokens for a wedding party: 24 wooden coins 30 mm across, cut
# from 3 mm birch, laid out 6 across and 4 down with 3 mm between them so they
# come out of one 200 x 140 mm blank. Each coin is engraved with a border ring
# 2 mm in from its edge, "ONE DRINK" round the top, the date "14.06.27" round
# the bottom (readable, not upside down), and the couple's initials "A&J" in
# the middle in bold filled letters 7 mm tall.

units mm
thickness 3 mm

param coin_d = 30 mm, min = 25 mm, max = 40 mm
param gap = 3 mm, min = 2 mm, max = 6 mm
param rows = 4, min = 1, max = 6
param cols = 6, min = 1, max = 8

def token() -> solid {
    disc = Circle(center=(0, 0), diameter=coin_d)
    drawing face {
        border = Circle(center=(0, 0), radius=coin_d / 2 - 2)
        top_ring = Circle(center=(0, 0), radius=coin_d / 2 - 6, construction=true)
        bottom_ring = Circle(center=(0, 0), radius=coin_d / 2 - 2.5, construction=true)
        top = Text("ONE DRINK", along=top_ring, size=3.5)
        date = Text("14.06.27", along=bottom_ring, size=3.5, flip=true)
        initials = Text("A&J", position=(0, 0), size=7, font="sans:Bold", valign="middle",
                        fill=true)
    }
}

assembly tokens {
    first = token()
    coins = GridPattern(first, rows, cols, (coin_d + gap, coin_d + gap))

    assert len(coins) == 24, "24 coins"
    assert first.disc.diameter == 30 mm, "coins 30 mm across"
    assert coins[1].disc.center.x - coins[0].disc.center.x == 33 mm, "3 mm between coins"
    assert self.bb.width <= 200 mm and self.bb.height <= 140 mm, "fits the 200 x 140 blank"
    assert first.face.initials.size == 7 mm, "initials 7 mm tall"
}
