# Request (signs): a depth gauge board for the ford on our farm lane, 9 mm marine ply,
# 150 mm wide, reading 0 to 1.0 m from the road surface at its bottom edge, cut in two
# sections that fit my 600 x 400 bed and screw to the post one above the other:
# - lower section 565 mm high (0 to 0.565 m), upper 530 mm (0.565 m to the top); the lower
#   one's bottom corners and the upper one's top corners rounded 10 mm.
# - At every 0.1 m a filled bar 50 x 8 mm centred on the level, 20 mm from the board's middle
#   line to the right, and the level ("0.1" ... "1.0") in filled bold 30 mm figures centred
#   on the level, 20 mm left of the middle; at every 0.05 m between them a filled 25 x 4 mm
#   bar, its right end flush with the long bars'. (40 mm figures 15 mm left, as first asked,
#   ran into the bars: a 150 mm board has no room for them.)
# - "DEPTH m" in filled bold 28 mm letters (at most 130 mm wide) across the upper section,
#   centred 40 mm below its top.
# - Three 6.5 mm holes per section for 6 mm screws, countersunk 13 mm, 60 mm left of the
#   middle line: 40 mm above the section's bottom, 100 mm below its top, and halfway.
# FIX after the first valid program: on the upper section those heights put the screw heads
#   3-5 mm from "0.6", "0.8" and "1.0"; its screws go in the gaps between the figures
#   instead, 85, 285 and 385 mm above its bottom (the lower one's stay at 40, 252.5, 465).

t = 9 mm
thickness t

def section(first=1, last=11, bottom=0 mm, height=565 mm, header=false,
            screws_at=[40 mm, 252.5 mm, 465 mm]) -> solid {
    body = RoundedRectangle(center=(0, height / 2), width=150, height=height,
                            corner_radii=[10, 10, 0, 0] if header else [0, 0, 10, 10])
    drawing bars {
        for k in [j for j in range(first, last + 1) if j % 2 == 0] {
            bar = Rectangle(center=(45, k * 50 mm - bottom), width=50, height=8, fill=true)
        }
        for k in [j for j in range(first, last + 1) if j % 2 == 1] {
            tick = Rectangle(center=(57.5, k * 50 mm - bottom), width=25, height=4, fill=true)
        }
    }
    drawing nums {
        for k in [j for j in range(first, last + 1) if j % 2 == 0] {
            num = Text(f"{k * 0.05:.1f}", position=(-20, k * 50 mm - bottom), size=30,
                       font="sans:Bold", valign="middle", fill=true)
        }
    }
    if header {
        drawing head {
            word = Text("DEPTH m", position=(0, height - 40 mm), size=28, font="sans:Bold",
                        valign="middle", fill=true, max_width=130 mm)
        }
    }
    hole screws {
        for j in range(3) {
            c = Circle(center=(-60, screws_at[j]), diameter=6.5)
        }
    }
    Countersink(screws, diameter=13 mm)
}

assembly ford_gauge {
    lower = section(first=1, last=11, bottom=0 mm, height=565 mm, header=false)
    upper = section(first=12, last=20, bottom=565 mm, height=530 mm, header=true,
                    screws_at=[85 mm, 285 mm, 385 mm])

    # 3D: on the post, facing the lane, the upper one on top of the lower
    Place(lower, position=(0, 0, 0), face="front", up="up")
    Place(upper, position=(0, 0, 565 mm), face="front", up="up")

    # flat layout for cutting
    RightOf(upper, lower, gap=6 mm)
    AlignBottom(upper, lower)

    # the request's numbers
    assert lower.body.width == 150 mm and upper.body.width == 150 mm, "150 wide"
    assert lower.body.height == 565 mm and upper.body.height == 530 mm, "565 and 530 high"
    assert lower.body.height <= 600 mm and upper.body.height <= 600 mm, "fit the bed"
    assert len(lower.bars.bar) == 5 and len(upper.bars.bar) == 5, "ten 0.1 m bars"
    assert len(lower.bars.tick) == 6 and len(upper.bars.tick) == 4, "ten 0.05 m bars"
    assert lower.bars.bar[0].center.y - lower.body.bb.bottom == 100 mm, "0.1 m at 100 mm"
    assert lower.bars.tick[0].center.y - lower.body.bb.bottom == 50 mm, "0.05 m at 50 mm"
    assert upper.bars.bar[0].center.y - upper.body.bb.bottom + 565 mm == 600 mm, "0.6 m at 600 mm"
    assert upper.bars.bar[4].center.y - upper.body.bb.bottom + 565 mm == 1000 mm, "1.0 m at 1000 mm"
    assert lower.nums.num[0].text == "0.1" and upper.nums.num[4].text == "1.0", "figures"
    assert lower.bars.bar[0].bb.left - lower.body.center.x == 20 mm, "bars 20 right of the middle"
    assert lower.bars.tick[0].bb.right == lower.bars.bar[0].bb.right, "short bars flush right"
    assert lower.nums.num[0].position.x - lower.body.center.x == -20 mm, "figures 20 left"
    assert distance(lower.nums, lower.bars) >= 3 mm and distance(upper.nums, upper.bars) >= 3 mm,
        "figures clear of the bars"
    assert distance(lower.nums, lower.screws) >= 3 mm and distance(upper.nums, upper.screws) >= 3 mm,
        "figures clear of the screws"
    assert distance(upper.head, upper.screws) >= 3 mm and distance(upper.head, upper.nums) >= 3 mm,
        "header clear"
    assert upper.body.bb.top - upper.head.word.position.y == 40 mm, "header 40 below the top"
    assert lower.screws.c[0].center.y - lower.body.bb.bottom == 40 mm, "screw 40 up"
    assert lower.body.bb.top - lower.screws.c[2].center.y == 100 mm, "screw 100 down"
    assert lower.screws.c[0].center.x - lower.body.center.x == -60 mm, "screws 60 left"
    assert upper.screws.c[1].center.y - upper.body.bb.bottom == 285 mm, "upper screws between figures"
    assert distance(upper.nums, upper.screws) >= 10 mm, "upper screw heads well clear of the figures"
    assert lower.bars.tick[5].bb.top < lower.body.bb.top and upper.nums.num[0].bb.bottom > upper.body.bb.bottom,
        "no mark runs off a section"
}
