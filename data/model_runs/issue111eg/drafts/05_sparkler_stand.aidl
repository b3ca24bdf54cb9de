# Request: a sparkler stand for a wedding send-off, in 3 mm ply: a closed finger-jointed box
# 160 long x 100 deep x 80 tall (outside), 10 mm fingers. The lid has 32 holes of 6 mm,
# 4 rows x 8 on a 16 mm pitch, centred, for the sparklers' wires to stand in. The front is
# engraved filled: "LET LOVE SPARKLE" in serif italic, 12 mm capitals (at most 130 mm long),
# and below it "ANNA & JOE  14.06.2027" in serif, 6 mm.

units mm
thickness 3 mm
import "std/joints.aidl"

assembly sparkler_stand {
    box = finger_box(length=160 mm, depth=100 mm, height=80 mm, thickness=3 mm, finger=10 mm,
                     closed=true)

    hole spark { c = Circle(center=(0, 0), diameter=6) }
    sparks = GridPattern(spark, 4, 8, (16, 16))
    At(spark.c.center, box.lid.bb.center, dx=-3.5 * 16 mm, dy=-1.5 * 16 mm)
    CutInto(spark, box.lid)

    drawing words {
        motto = Text("LET LOVE SPARKLE", position=(0, 8), size=12, font="serif:Italic",
                     max_width=130 mm, valign="middle", fill=true)
        names = Text("ANNA & JOE  14.06.2027", position=(0, -14), size=6, font="serif",
                     valign="middle", fill=true)
    }
    CenterInside(words, box.front)
    CutInto(words, box.front)

    assert len(sparks) == 32, "32 sparkler holes"
    assert sparks[1].c.center.x - sparks[0].c.center.x == 16 mm, "16 mm pitch across"
    assert sparks[8].c.center.y - sparks[0].c.center.y == 16 mm, "16 mm pitch between rows"
    assert spark.c.diameter == 6 mm, "6 mm holes"
    assert box.front.bb.width == 160 mm and box.front.bb.height == 80 mm, "front 160 x 80"
    assert box.left.bb.height == 100 mm, "100 deep"
    assert sparks[0].c.bb.left - box.lid.bb.left >= 15 mm, "holes clear of the lid's fingers"
    assert box.lid.bb.top - sparks[31].c.bb.top >= 15 mm, "holes clear of the lid's fingers"
    assert words.motto.bb.width <= 130 mm, "motto at most 130 long"
    assert words.bb.left - box.front.bb.left >= 10 mm, "words clear of the front's fingers"
    assert box.front.bb.top - words.bb.top >= 10 mm, "words clear of the front's fingers"
    assert words.bb.bottom - box.front.bb.bottom >= 10 mm, "words clear of the front's fingers"
}
