# Request (pets): a keepsake urn box for our cat Miso's ashes (the vet's bag is about
# 120 x 80 x 60 mm).
# - box: 6 mm birch ply, finger-jointed (15 mm fingers), 160 long x 120 deep x 130 high
#   outside with a lift-off lid (the lid box kind, with a lip under the lid).
# - lid: engraved filled: a paw print (a 16 x 13 pad and four toes) above, "MISO" in 18 mm
#   bold serif in the middle, "2011 - 2026" in 7 mm below; the whole group centred on the
#   lid.
# - photo frame on the front, 3 mm ply, two layers glued on: a spacer 71 x 96 with a
#   53 mm wide pocket, 10 mm above its foot and open at its top (a 51 x 76 mm wallet photo slides in from above) and a
#   frame 71 x 96 R4 with a 45 x 70 R2 window (3 mm over the photo all round), centred on
#   the front.

units mm
thickness 6 mm

import "std/boxes.aidl"

box_l = 160 mm
box_w = 120 mm
box_h = 130 mm
ply = 6 mm
thin = 3 mm
photo_w = 51 mm
photo_h = 76 mm
frame_w = 71 mm
frame_h = 96 mm

assembly urn {
    box = lid_box(length=box_l, width=box_w, height=box_h, thickness=ply, finger=15 mm)

    drawing memorial {
        field = Rectangle(center=(0, 0), width=box_l, height=box_w, construction=true)
        pad = Ellipse(center=(0, 26), rx=8, ry=6.5, fill=true)
        toe_1 = Ellipse(center=(-11.5, 33), rx=3, ry=4.2, rotation=25 deg, fill=true)
        toe_2 = Ellipse(center=(-4, 38.5), rx=3, ry=4.2, rotation=8 deg, fill=true)
        toe_3 = Ellipse(center=(4, 38.5), rx=3, ry=4.2, rotation=-8 deg, fill=true)
        toe_4 = Ellipse(center=(11.5, 33), rx=3, ry=4.2, rotation=-25 deg, fill=true)
        name = Text("MISO", position=(0, 0), size=18, font="serif:Bold", valign="middle",
                    fill=true)
        dates = Text("2011 - 2026", position=(0, -24), size=7, font="sans", valign="middle",
                     fill=true)
    }
    CenterInside(memorial.field, box.lid)
    CutInto(memorial, box.lid)

    solid spacer {
        thickness 3 mm
        plate = Rectangle(center=(0, 0), width=71, height=96)
        hole pocket {
            p = Rectangle(center=(0, -96 / 2 + 10 + 88 / 2), width=53, height=88)
        }
    }

    solid frame {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, 0), width=71, height=96, corner_radius=4)
        hole window {
            w = RoundedRectangle(center=(0, 0), width=45, height=70, corner_radius=2)
        }
    }

    # 3D: the box as the template stands it; spacer then frame on the front's face,
    # centred on the wall below the lid
    Place(spacer, position=(0, -box_w / 2, (box_h - ply) / 2), face="front", up="up")
    Place(frame, position=(0, -box_w / 2 - thin, (box_h - ply) / 2), face="front", up="up")

    # the sheet
    RightOf(frame, box, gap=10)
    AlignTop(frame, box)
    Below(spacer, frame, gap=8)
    AlignLeft(spacer, frame)

    # the request's numbers
    assert box.body.front.bb.width == 160 mm, "160 long"
    assert box.lid.bb.width == 160 mm and box.lid.bb.height == 120 mm, "lid 160 x 120"
    assert box_l - 2 * ply > 120 mm and box_w - 2 * ply > 80 mm, "the bag fits"
    assert spacer.plate.bb.width == frame_w and spacer.plate.bb.height == frame_h, "spacer"
    assert frame.plate.bb.width == frame_w and frame.plate.bb.height == frame_h, "frame"
    assert spacer.pocket.p.width - photo_w == 2 mm, "1 mm play each side for the photo"
    assert spacer.plate.bb.top - spacer.pocket.p.bb.top < 0 mm, "pocket open at the top"
    assert spacer.pocket.p.bb.bottom - spacer.plate.bb.bottom == (frame_h - photo_h) / 2,
        "the photo sits centred behind the window"
    assert (photo_w - frame.window.w.width) / 2 == 3 mm, "3 mm over the photo (sides)"
    assert (photo_h - frame.window.w.height) / 2 == 3 mm, "3 mm over the photo (height)"
    assert frame.window.w.bb.bottom - frame.plate.bb.bottom >= spacer.pocket.p.bb.bottom -
        spacer.plate.bb.bottom, "window over the pocket"
    assert memorial.name.size == 18 mm and memorial.dates.size == 7 mm, "letter sizes"
    assert memorial.pad.rx == 8 mm and memorial.pad.ry == 6.5 mm, "16 x 13 pad"
    assert frame_h < box_h - ply - 2 * ply - 10 mm, "frame clear of the fingers"
}
