# Request (music): a half-moon hand tambourine from three glued layers of 4 mm birch ply. Each
# layer is a ring segment: outer radius 120 mm, inner 80 mm (a 40 mm band), running from 188 to
# 352 degrees (the grip at the bottom, 270), its four corners rounded 8 mm. Four jingle windows
# 42 mm along the band x 16 mm across, centred on radius 100 mm at 206, 236, 304 and 334 degrees
# (so a 44-degree grip is left clear in the middle), in all three layers. The middle layer also
# has a 2.2 mm channel for a 2 mm steel pin running across each window, 8 mm into the wood on
# both sides; the pins hold pairs of 38 mm jingles. Layers laid out side by side for cutting.

thickness 4 mm

param r_out = 120 mm, min = 100 mm, max = 150 mm
param band_w = 40 mm, min = 30 mm, max = 50 mm
param pin = 2.2 mm, min = 1.8 mm, max = 3.2 mm

r_mid = r_out - band_w / 2
angles = [206 deg, 236 deg, 304 deg, 334 deg]

def layer(mid=false) -> solid {
    band = Sector(center=(0, 0), radius=r_out, start_angle=188 deg, end_angle=352 deg,
                  inner_radius=r_out - band_w)
    Fillet(band, 8)
    for k in range(4) {
        hole win {
            w = Rectangle(center=polar((0, 0), r_mid, angles[k]), width=42, height=16,
                          rotation=angles[k] + 90 deg)
        }
    }
    if mid {
        for k in range(4) {
            hole pinway {
                p = Rectangle(center=polar((0, 0), r_mid, angles[k]), width=16 + 2 * 8, height=pin,
                              rotation=angles[k])
            }
        }
    }
}

assembly tambourine {
    front = layer()
    middle = layer(mid=true)
    back = layer()
    RightOf(middle, front, gap=5)
    RightOf(back, middle, gap=5)
    AlignTop(middle, front)
    AlignTop(back, front)

    assert front.band.radius == 120 mm and front.band.inner_radius == 80 mm, "band 120 / 80"
    assert len(front.win) == 4 and len(middle.win) == 4 and len(back.win) == 4, "four windows per layer"
    assert len(middle.pinway) == 4, "a pin channel per window"
    assert front.win[0].w.width == 42 mm and front.win[0].w.height == 16 mm, "window 42 x 16"
    assert middle.pinway[0].p.width - middle.win[0].w.height == 16 mm, "pin 8 mm into the wood each side"
    assert angles[2] - angles[1] == 68 deg, "grip: 44 deg clear between the inner windows' edges"
}
