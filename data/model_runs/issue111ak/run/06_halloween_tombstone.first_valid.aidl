# Holidays: a Halloween lawn tombstone with a skeleton hand, 6 mm exterior ply, two parts
# each pushed into the lawn on its own stakes:
# - the tombstone: 300 mm wide, 400 mm tall above the ground, a rectangle with a
#   semicircular top (radius 150 mm); "RIP" cut through in bold stencil letters 70 mm
#   tall (at most 180 mm wide), their baseline 260 mm above the ground; "HERE LIES" (16 mm)
#   and "BAD CODE" (22 mm) engraved below; a crack cut as a zig-zag slit from the top
#   left of the arch, 60 mm long at most, off the letters; two pointed stakes 40 mm wide
#   reaching 240 mm into the ground, 180 mm apart centre to centre;
# - a skeleton hand "rising from the grave": a palm 50 x 55 mm (R8 corners), four bony
#   fingers 9 mm wide (50, 60, 58 and 45 mm long) bent like claws, a thumb, and a 24 mm
#   wrist that becomes a pointed stake 250 mm below the palm.

units mm
thickness 6 mm

stone_w = 300 mm
stone_h = 400 mm
stake_w = 40 mm
stake_depth = 240 mm
stake_pitch = 180 mm

def stake(x) -> solid {
    s = Polygon([(x - stake_w / 2, 10), (x - stake_w / 2, -stake_depth + 40), (x, -stake_depth),
                 (x + stake_w / 2, -stake_depth + 40), (x + stake_w / 2, 10)])
}

assembly graveyard {
    solid tombstone {
        # y = 0 is the ground line
        slab = Rectangle(corner=(-stone_w / 2, 0), opposite=(stone_w / 2, stone_h - stone_w / 2))
        arch = Circle(center=(0, stone_h - stone_w / 2), radius=stone_w / 2)
        left_stake = stake(-stake_pitch / 2)
        right_stake = stake(stake_pitch / 2)
        hole rip {
            word = Text("RIP", position=(0, 260), size=70, font="sans:Bold", stencil=true,
                        max_width=180)
        }
        drawing epitaph {
            line1 = Text("HERE LIES", position=(0, 200), size=16)
            line2 = Text("BAD CODE", position=(0, 150), size=22)
        }
        cut crack {
            c = Polyline([polar((0, stone_h - stone_w / 2), stone_w / 2, 150 deg),
                          (-112, 312), (-120, 296), (-104, 284), (-110, 270)])
        }
    }

    solid hand {
        palm = RoundedRectangle(center=(0, 0), width=50, height=55, corner_radius=8)
        lengths = [50, 60, 58, 45]
        for i in range(4) {
            x = -18 + i * 12
            f = Stroke(Polyline([(x, 20), (x * 1.3, 20 + lengths[i] * 0.55),
                                 (x * 1.6 - 5, 20 + lengths[i])]), width=9, cap="round")
        }
        thumb = Stroke(Polyline([(-20, -5), (-40, 12), (-44, 30)]), width=10, cap="round")
        wrist = Polygon([(-12, -20), (-12, -250 + 30), (0, -250), (12, -250 + 30), (12, -20)])
    }

    RightOf(hand, tombstone, gap=20)
    AlignTop(hand, tombstone)

    assert tombstone.slab.width == 300 mm, "300 mm wide"
    assert tombstone.arch.bb.top - tombstone.slab.bb.bottom == 400 mm, "400 mm above ground"
    assert tombstone.arch.radius == 150 mm, "R150 top"
    assert tombstone.rip.word.size <= 70 mm and tombstone.rip.word.bb.width <= 180 mm,
        "RIP 70 mm, at most 180 wide"
    assert tombstone.rip.word.position.y - tombstone.slab.bb.bottom == 260 mm, "RIP at 260"
    assert tombstone.slab.bb.bottom - tombstone.left_stake.s.bb.bottom == 240 mm,
        "stakes 240 mm deep"
    assert tombstone.left_stake.s.bb.width == 40 mm, "40 mm stakes"
    assert (tombstone.right_stake.s.bb.center_x - tombstone.left_stake.s.bb.center_x
            == 180 mm), "stakes 180 apart"
    assert hand.palm.width == 50 mm and hand.palm.height == 55 mm, "palm 50 x 55"
    assert len(hand.f) == 4, "four fingers"
    assert hand.palm.bb.bottom - hand.wrist.bb.bottom == 250 mm - 27.5 mm, "stake 250 below palm centre"
}
