# A name tag: a rounded card with a lanyard slot, an engraved border, a
# "HELLO my name is" header, the name (shrunk to fit) and a title, and a row
# of decorative dots made by a loop. The texts are stacked with Below.
# Try: --set name='"GRACE HOPPER"'  --set width=100  --set title='"Rear Admiral"'

param name = "ADA LOVELACE"
param title = "Analytical Engine Programmer"
param width = 90 mm
param height = 55 mm, min = 25 mm

assert len(name) > 0, "the name cannot be empty"
name_size = min(8 mm, (width - 20 mm) / max(len(name), 1))  # shrink long names to fit

solid tag {
    card = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=5)

    hole lanyard {
        slot = Slot(center=(0, height / 2 - 6), length=18, width=4)
    }

    drawing face {
        border = RoundedRectangle(center=(0, -2), width=width - 8, height=height - 16,
                                  corner_radius=3)
        hello = Text("HELLO my name is", (0, 12), size=4)
        who = Text(name, (0, -4), size=name_size)
        role = Text(title, (0, -15), size=3)
        for i in range(9) {
            dot = Circle(center=(-20 + i * 5 mm, -17.5), radius=0.8)
        }
        # header, name and title stacked down the card, centered
        Below(who, hello, gap=6)
        Below(role, who, gap=5)
        AlignCenterX(who, border)
        AlignCenterX(hello, border)
        AlignCenterX(role, border)
    }

    # the lanyard slot is centered near the top, above the border
    AlignCenterX(lanyard, card)
    lanyard.bb.top == card.bb.top - 4
    AlignCenterX(face, card)
    face.border.center.y == card.center.y - 2
}
