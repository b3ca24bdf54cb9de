# Request (parties): a "Who am I?" party-game headband for children, cut from 3 mm birch
# ply. A band 560 mm long and 30 mm wide with round ends, made to bend round the head by
# two living hinges 150 mm long beside a rigid 100 mm front; its two ends overlap at the
# back and are joined with an M4 nylon screw through one of 5 holes (4.2 mm, 10 mm apart)
# at each end, for heads of 460 to 540 mm. On the front the band rises into a back plate
# 72 mm wide and 95 mm tall (its bottom on the band's bottom edge) for a poker card
# (63 x 88 mm): glued on it a U-shaped spacer (4 mm side bars, 4 mm bottom bar) and a
# U-shaped front frame whose side bars overlap the card by at least 3 mm and whose 16 mm
# bottom bar carries "WHO AM I?" engraved 6 mm high. The card slides in from the top.

import "std/plates.aidl"

t = 3 mm
thickness t

band_l = 560 mm
band_w = 30 mm
front_l = 100 mm
hinge_l = 150 mm
plate_w = 72 mm
plate_h = 95 mm
pb = -band_w / 2              # the plate's bottom: the band's bottom edge
card_w = 63 mm
card_h = 88 mm
bar = 4 mm
front_bar = (plate_w - 56 mm) / 2     # 8 mm: overlaps the card by 4.5 mm
text_bar = 16 mm
hole_x0 = front_l / 2 + hinge_l + 30 mm   # the first hole at each end

assembly headband {
    solid band {
        strip = Slot(center=(0, 0), length=band_l, width=band_w)
        plate = Rectangle(bottom_left=(-plate_w / 2, pb), width=plate_w, height=plate_h)
        right_hinge = living_hinge(width=hinge_l, height=band_w, pitch=2 mm, cut=12 mm,
                                   bridge=3 mm, cx=front_l / 2 + hinge_l / 2, cy=0 mm)
        left_hinge = living_hinge(width=hinge_l, height=band_w, pitch=2 mm, cut=12 mm,
                                  bridge=3 mm, cx=-front_l / 2 - hinge_l / 2, cy=0 mm)
        hole sizes {
            for i in range(5) {
                r = Circle(center=(hole_x0 + i * 10 mm, 0), diameter=4.2)
                l = Circle(center=(-hole_x0 - i * 10 mm, 0), diameter=4.2)
            }
        }
    }

    solid spacer {
        left = Rectangle(bottom_left=(-plate_w / 2, pb), width=bar, height=plate_h)
        right = Rectangle(bottom_left=(plate_w / 2 - bar, pb), width=bar, height=plate_h)
        floor = Rectangle(bottom_left=(-plate_w / 2, pb), width=plate_w, height=bar)
    }

    solid front {
        left = Rectangle(bottom_left=(-plate_w / 2, pb), width=front_bar, height=plate_h)
        right = Rectangle(bottom_left=(plate_w / 2 - front_bar, pb), width=front_bar, height=plate_h)
        floor = Rectangle(bottom_left=(-plate_w / 2, pb), width=plate_w, height=text_bar)
        drawing words {
            w = Text("WHO AM I?", position=(0, pb + text_bar / 2), size=6, valign="middle")
        }
    }

    Above(spacer, band, gap=5)
    AlignLeft(spacer, band)
    RightOf(front, spacer, gap=5)
    AlignBottom(front, spacer)

    Place(band, position=(0, 0, 0))
    Place(spacer, position=(0, 0, t))
    Place(front, position=(0, 0, 2 * t))

    assert band.strip.length == 560 mm and band.strip.width == 30 mm
    assert band.plate.width == 72 mm and band.plate.height == 95 mm
    assert band.plate.bb.bottom == band.strip.bb.bottom, "plate's bottom on the band's bottom edge"
    assert spacer.right.bb.left - spacer.left.bb.right >= 63 mm + 0.5 mm, "the card slides in"
    assert (spacer.right.bb.left - spacer.left.bb.right) - (front.right.bb.left - front.left.bb.right) >= 2 * 3 mm,
        "the frame holds the card by 3 mm each side"
    assert band.plate.bb.top - spacer.floor.bb.top >= 88 mm, "the card's height fits above the floor"
    assert front.floor.height == 16 mm and front.words.w.size == 6 mm
    assert len(band.sizes.r) == 5 and len(band.sizes.l) == 5
    # the loop's length at the outermost and innermost holes
    assert 2 * hole_x0 == 460 mm and 2 * (hole_x0 + 40 mm) == 540 mm, "heads of 460 to 540 mm"
    assert band.right_hinge.bb.left >= front_l / 2 and band.right_hinge.bb.right <= hole_x0 - 10 mm
}
