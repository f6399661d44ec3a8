<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DateTime time="10:00:00" date="2026-11-23"/>
  <User name="slicereuse"/>
  <DataFileName name="member_000.ply"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-12.5" y="3.25" z="1e-3" active="1" name="left molar"/>
 <point name='a &amp; b' z="3" active="0" x="4" y="5"/>
 <!-- <point x="9" y="9" z="9" name="comment"/> -->
 <point x="7" y="8" z="9" name="old&#65;"/>
 <point x="0.5" y="-2" z="14.25" active="1" name="incisor"/>
</PickedPoints>
