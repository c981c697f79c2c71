//! Builders of the XML elements of a TwinCAT 3 CFC chart (`<CFC>` as TwinCAT saves it in a
//! `.TcPOU`), for the tests that write charts: pins, input and output elements, wires.

/// A pin of a box, its id `id`.
pub fn cfc_pin(id: u32) -> String {
    format!(r#"<o><v n="Negated">false</v><v n="Id">{id}L</v></o>"#)
}

/// The text of an input or output element (a variable, a literal).
pub fn cfc_text(text: &str) -> String {
    format!(r#"<o n="Text" t="CFCText"><v n="Text">"{text}"</v></o>"#)
}

/// An input element reading `text`, its output pin `pin`, at `x, y`.
pub fn cfc_input(text: &str, pin: u32, x: u32, y: u32) -> String {
    format!(
        r#"<o t="CFCInputElement"><o n="Output" t="CFCOutputPin"><v n="Negated">false</v><v n="Id">{pin}L</v></o>{}<v n="Bounds">"{x}, {y}, 0, 0"</v></o>"#,
        cfc_text(text)
    )
}

/// An output element writing `text`, its input pin `pin`, at `x, y`.
pub fn cfc_output(text: &str, pin: u32, x: u32, y: u32) -> String {
    format!(
        r#"<o t="CFCOutputElement"><o n="Input" t="CFCInputPinWithSetReset"><v n="Negated">false</v><v n="SetReset" t="SetReset">None</v><v n="Id">{pin}L</v></o>{}<v n="Bounds">"{x}, {y}, 0, 0"</v></o>"#,
        cfc_text(text)
    )
}

/// A connection from the output pin `from` to the input pin `to`.
pub fn cfc_wire(from: u32, to: u32) -> String {
    format!(r#"<o t="CFCConnection"><v n="SourcePinId">{from}L</v><v n="DestPinId">{to}L</v></o>"#)
}
