# Request (holidays): a Christmas Eve box for our daughter (pyjamas, a book, cocoa), from
# 6 mm birch ply: a finger-jointed box with a hinged lid, 400 x 300 x 200 mm outside,
# 20 mm fingers. Lid engraved filled: "Christmas Eve" in bold italic serif, 40 mm, at most
# 340 mm wide, and "ELLA" under it in bold sans, 30 mm; a row of 13 small five-point
# stars (16 mm across the tips, 30 mm apart) along the lid's front and back edges, 30 mm
# in. The front panel gets a five-point star window 60 mm across its tips cut through its
# middle, and a 30 mm round thumb notch in the middle of its top edge to lift the lid.

units mm
thickness 6 mm
import "std/boxes.aidl"

assembly eve_box {
    box = hinged_box(length=400 mm, width=300 mm, height=200 mm, thickness=6 mm,
                     finger=20 mm)

    drawing words {
        title = Text("Christmas Eve", position=(0, 20), size=40, font="serif:Bold Italic",
                     valign="middle", max_width=340, fill=true)
        name = Text("ELLA", position=(0, -45), size=30, font="sans:Bold",
                    valign="middle", fill=true)
    }
    CutInto(words, box.lid)
    CenterInside(words, box.lid)

    drawing stars {
        s = Star(center=(-180, 120), points=5, outer_radius=8, inner_radius=3.5, fill=true)
        top_row = LinearPattern(s, 13, (30, 0))
        b = Star(center=(-180, -120), points=5, outer_radius=8, inner_radius=3.5, fill=true)
        bottom_row = LinearPattern(b, 13, (30, 0))
    }
    CutInto(stars, box.lid)
    CenterInside(stars, box.lid)

    hole window {
        st = Star(center=(0, 0), points=5, outer_radius=30, inner_radius=12)
    }
    CutInto(window, box.front)
    CenterInside(window, box.front)

    hole notch {
        c = Circle(center=(0, 0), diameter=30)
    }
    CutInto(notch, box.front)
    AlignCenterX(notch, box.front)
    notch.c.center.y == box.front.bb.top

    assert box.length == 400 mm and box.width == 300 mm and box.height == 200 mm, "size"
    assert box.finger == 20 mm, "20 mm fingers"
    assert words.title.bb.width <= 340 mm, "title fits"
    assert len(stars.top_row) == 13 and len(stars.bottom_row) == 13, "13 stars a row"
    assert stars.top_row[1].center.x - stars.top_row[0].center.x == 30 mm, "stars 30 apart"
    assert stars.s.outer_radius * 2 == 16 mm, "stars 16 across"
    assert box.lid.bb.top - stars.top_row[0].center.y == 30 mm, "stars 30 in"
    assert stars.bottom_row[0].center.y - box.lid.bb.bottom == 30 mm, "stars 30 in"
    assert distance(words, stars) >= 10 mm, "words clear of the stars"
    assert window.st.outer_radius * 2 == 60 mm, "window 60 across"
    assert distance(window, notch) >= 20 mm, "window clear of the notch"
}
