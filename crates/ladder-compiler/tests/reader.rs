//! Reading projects: schema versions, BOM, declarations, configurations, malformed input.

mod common;

use common::{compile, dump_unit, fixture};
use ladder_compiler::ast::*;

#[test]
fn v1_file_with_bom_reads_types_pous_and_configuration() {
    let xml = fixture("v1_bom_types.xml");
    assert!(xml.starts_with('\u{feff}'));
    let (unit, diags) = compile("v1_bom_types.xml", &xml);
    // The ST function is lowered to IL like the FBD program that calls it.
    assert_eq!(diags.matches("error[").count(), 0, "{diags}");
    assert!(dump_unit(&unit).contains("FUNCTION Twice"), "ST body kept");
    let LibraryElement::DataTypes(types) = &unit.items[0] else {
        panic!("data types first")
    };
    let names: Vec<&str> = types.iter().map(|t| t.name.name.as_str()).collect();
    assert_eq!(names, ["Color", "Point", "Row", "Percent", "Name"]);
    assert!(
        matches!(&types[0].def, TypeDef::Enum { values, init: Some(i) } if values.len() == 2 && i.name == "green")
    );
    assert!(
        matches!(&types[1].def, TypeDef::Struct { fields } if fields.len() == 2 && fields[0].init.is_some())
    );
    assert!(matches!(&types[2].def,
        TypeDef::Alias { ty: TypeRef::Array { dims, .. }, init: Some(Initializer::Array(e, _)) }
            if dims[0].upper == 8 && e[0].repeat == Some(8)));
    assert!(matches!(
        &types[3].def,
        TypeDef::Alias {
            ty: TypeRef::Subrange { upper: 100, .. },
            ..
        }
    ));
    assert!(matches!(
        &types[4].def,
        TypeDef::Alias {
            ty: TypeRef::String {
                length: Some(20),
                wide: false,
                ..
            },
            ..
        }
    ));
    // The span of a declaration points at its XML element.
    let color = &types[0];
    assert_eq!(&xml[color.name.span.range()], "Color");
    let LibraryElement::Pou(twice) = &unit.items[1] else {
        panic!()
    };
    assert_eq!(twice.kind, PouKind::Function);
    assert!(!twice.body.is_empty(), "the ST body is lowered");
    let LibraryElement::Pou(main) = &unit.items[2] else {
        panic!()
    };
    assert!(main.var_blocks[0].retain);
    assert_eq!(
        main.var_blocks[0].vars[1].location.as_ref().unwrap().path,
        [0, 1]
    );
    assert_eq!(main.var_blocks[1].kind, VarKind::External);
    insta::assert_snapshot!(dump_unit(&unit));
    let LibraryElement::Configuration(cfg) = &unit.items[3] else {
        panic!()
    };
    assert_eq!(cfg.globals[0].vars[0].name.name, "Limit");
    let res = &cfg.resources[0];
    assert_eq!(res.tasks.len(), 2);
    assert!(
        matches!(&res.tasks[0].interval, Some(Operand::Literal(l)) if l.kind == LiteralKind::Duration(10_000_000))
    );
    assert_eq!(res.tasks[0].priority, Some(2));
    assert!(matches!(&res.tasks[1].single, Some(Operand::Var(v)) if v.base.name == "In1"));
    assert_eq!(res.programs[0].type_name.name, "main");
    assert!(res.programs[0].task.is_none());
}

#[test]
fn malformed_xml_is_reported_at_its_position() {
    let (_, diags) = compile(
        "bad.xml",
        "<project>\n  <types>\n    <pous></types>\n</project>",
    );
    assert!(diags.contains("bad.xml:3:11: error[E3001]"), "{diags}");
}

#[test]
fn a_file_that_is_not_a_project_is_reported() {
    let (unit, diags) = compile("x.xml", "<?xml version=\"1.0\"?><plcProject/>");
    assert!(unit.items.is_empty());
    assert!(
        diags.contains("E3002") && diags.contains("<plcProject>"),
        "{diags}"
    );
    let (_, diags) = compile("empty.xml", "");
    assert!(diags.contains("E3002"), "{diags}");
}

#[test]
fn unknown_namespace_is_read_leniently_with_a_warning() {
    let xml = "<project xmlns=\"http://www.plcopen.org/xml/tc6_0300\"><types><pous>\
        <pou name=\"p\" pouType=\"program\"><interface/><body><LD/></body></pou></pous></types></project>";
    let (unit, diags) = compile("ns.xml", xml);
    assert!(
        diags.contains("W3001") && !diags.contains("error"),
        "{diags}"
    );
    assert!(matches!(&unit.items[0], LibraryElement::Pou(p) if p.name.name == "p"));
}
