# Request (gifts): a small gift box for a pair of cufflinks, 3 mm walnut plywood: a
# finger-jointed box with a sliding lid, 90 x 70 x 40 mm outside (10 mm fingers). On the lid,
# centred: the monogram "JHW" (serif bold, 12 mm, engraved filled) inside a filled engraved ring
# (18 mm radius, 1.5 mm wide), "FOR JAMES" engraved along the top of the ring (4 mm letters) and
# "14.06.2026" along its bottom, reading the right way up (4 mm). A matching 60 x 30 mm gift
# tag (corners 5 mm round) with a 4 mm cord hole 7 mm from its left end and "TO JAMES" /
# "FROM ANNA" engraved on two lines (5 mm).

import "std/boxes.aidl"
import "std/plates.aidl"

thickness 3 mm

assembly cufflink_box {
    k = sliding_lid_box(length=90 mm, width=70 mm, height=40 mm, thickness=3 mm, finger=10 mm)

    drawing crest {
        ring = Shell(Circle(center=(0, 0), radius=18), 1.5, fill=true)
        mono = Text("JHW", position=(0, 0), size=12, font="serif:Bold", valign="middle",
                    fill=true)
        over = text_on_arc(text="FOR JAMES", radius=22 mm, size=4 mm, angle=90 deg)
        under_ring = Circle(center=(0, 0), radius=24.5, construction=true)
        date = Text("14.06.2026", along=under_ring, size=4, flip=true)
    }
    CenterInside(crest, k.lid)
    CutInto(crest, k.lid)

    solid tag {
        card = RoundedRectangle(center=(0, 0), width=60, height=30, corner_radius=5)
        hole cord { c = Circle(center=(-23, 0), diameter=4) }
        drawing words {
            l1 = Text("TO JAMES", position=(5, 4), size=5, valign="middle")
            l2 = Text("FROM ANNA", position=(5, -5), size=5, valign="middle")
        }
    }
    RightOf(tag, k, gap=10)
    AlignTop(tag, k)
    # assembled: the tag lies on the lid
    Place(tag, position=(0, 0, 40), face="up")

    # the request's numbers
    assert k.length == 90 mm and k.width == 70 mm and k.height == 40 mm
    assert crest.mono.size == 12 mm
    assert crest.date.size == 4 mm and crest.over.size == 4 mm
    assert crest.ring.bb.width == 2 * (18 mm + 1.5 mm)
    assert tag.card.bb.width == 60 mm and tag.card.bb.height == 30 mm
    assert tag.cord.c.center.x - tag.card.bb.left == 7 mm and tag.cord.c.diameter == 4 mm
    assert tag.words.l1.size == 5 mm
    # the crest stays on the lid with a margin
    assert crest.bb.left >= k.lid.bb.left + 3 mm and crest.bb.right <= k.lid.bb.right - 3 mm
    assert crest.bb.bottom >= k.lid.bb.bottom + 3 mm and crest.bb.top <= k.lid.bb.top - 3 mm
    # the tag's words clear its cord hole
    assert tag.words.bb.left >= tag.cord.c.bb.right + 3 mm
}
