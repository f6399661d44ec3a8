<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DateTime time="10:00:00" date="2026-11-23"/>
  <User name="me"/>
  <DataFileName name="a.ply"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-12.5" y="3.25" z="1e-3" active="1" name="left molar"/>
 <point ="0.5" y"=" z='14.25' active='1' name='incisor'/>
 <point x="3.125" y="-7.5" z="2" active="0" name="canine"/>
 <point x="-4" y="6.75" z="0.5" active="1" name="premolar"/>
</PickedPoints>
