# Party place card: a 3 mm card 90 x 50 mm with 4 mm corner radii; the guest's name
# "SOPHIE" cut through as a stencil in sans Bold 12 mm, centred (middle 27 mm above the
# bottom edge); an engraved border line 4 mm inside the edge (82 x 42, R2); it stands on
# two feet 40 x 12 mm, cross-halved: the card has two 3 mm slots 6 mm deep up from its
# bottom edge, 60 mm apart and centred; each foot has one 6 mm deep slot down from the
# middle of its top edge (6 + 6 = the foot's 12 mm height).
import "std/joints.aidl"

thickness 3 mm

def foot() -> solid {
    base = Rectangle(center=(0, 0), width=40, height=12)
    slot = cross_halving(depth=6 mm, thickness=3 mm, cx=0 mm, cy=6 mm)
}

param name = "SOPHIE"

assembly place_card {
    solid card {
        body = RoundedRectangle(center=(0, 0), width=90, height=50, corner_radius=4)
        hole word {
            t = Text(name, (0, 0), size=12, font="sans:Bold", valign="middle",
                     stencil=true, max_width=76)
        }
        AlignCenterX(word, body)
        word.t.position.y == body.bb.bottom + 27 mm
        drawing border {
            r = RoundedRectangle(center=(0, 0), width=82, height=42, corner_radius=2)
        }
        CenterInside(border, body)
        left_slot = cross_halving(depth=6 mm, thickness=3 mm, rotation=180 deg, cx=-30 mm, cy=-25 mm)
        right_slot = cross_halving(depth=6 mm, thickness=3 mm, rotation=180 deg, cx=30 mm, cy=-25 mm)
    }

    foot1 = foot()
    foot2 = foot()
    Below(foot1, card, gap=8)
    AlignLeft(foot1, card)
    RightOf(foot2, foot1, gap=8)
    AlignBottom(foot2, foot1)

    assert card.body.bb.width == 90 mm and card.body.bb.height == 50 mm, "90 x 50 card"
    assert card.right_slot.cut.bb.center_x - card.left_slot.cut.bb.center_x == 60 mm, "slots 60 apart"
    assert card.left_slot.cut.bb.height == 6 mm, "card slots 6 deep"
    assert foot1.base.bb.width == 40 mm and foot1.base.bb.height == 12 mm, "40 x 12 feet"
    assert foot1.slot.cut.bb.height == 6 mm, "foot slots 6 deep"
    assert card.left_slot.cut.bb.height + foot1.slot.cut.bb.height == 12 mm, "halvings add to 12"
}
